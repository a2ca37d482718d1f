// SPDX-License-Identifier: GPL-3.0-or-later
// MFiX particle_input.dat, versions 1 and 2.0 (particles/particle_io.h).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>

#include "core/text.h"
#include "particles/particle_io.h"
#include "particles/text_fields.h"

namespace gridfree {
namespace {

constexpr int kV2DataLine = 35;  // "Data starts at line 35" (MFiX's own header text)

// One particle from fields x y z radius density [u v w].
ParticleSet read_v1(const std::filesystem::path& path, const std::vector<std::string>& lines) {
  ParticleSet set;
  set.source = path.string();
  ProblemList problems;
  for (std::size_t n = 0; n < lines.size() && problems.problems().size() < 20; ++n) {
    const int line_no = static_cast<int>(n) + 1;
    const auto fields = text::split(lines[n], " \t,", true);
    if (fields.empty()) continue;
    if (fields.size() != 5 && fields.size() != 8) {
      problems.add(text::at_line(path, line_no), "expected 5 columns (x y z radius density) or 8 (... u v w), got " +
                                                      std::to_string(fields.size()));
      continue;
    }
    double v[8] = {};
    bool ok = true;
    for (std::size_t i = 0; i < fields.size() && ok; ++i) {
      const auto x = text::parse_double(fields[i], true);
      if (!x) {
        problems.add(text::at_line(path, line_no),
                     std::string("column ").append(std::to_string(i + 1)).append(": '").append(fields[i]).append("' is not a finite number"));
        ok = false;
      } else {
        v[i] = *x;
      }
    }
    if (!ok) continue;
    if (!(v[3] > 0)) {
      problems.add(text::at_line(path, line_no), "the radius must be > 0");
      continue;
    }
    if (fields.size() == 8) set.has_velocity = true;
    set.particles.push_back({v[0], v[1], v[2], 2 * v[3], v[5], v[6], v[7]});
    set.source_lines.push_back(line_no);
  }
  problems.throw_if_any();
  return set;
}

struct V2Option {
  bool read = false;              // T: a column in the data
  std::vector<double> defaults;   // F: the values for every particle
  int line = 0;
};

ParticleSet read_v2(const std::filesystem::path& path, const std::vector<std::string>& lines) {
  ProblemList problems;
  int dimension = 0, line_of_dimension = 0;
  long count = -1;
  int line_of_count = 0;
  V2Option phase, diameter, density, velocity;
  const int header_end = std::min<int>(kV2DataLine - 1, static_cast<int>(lines.size()));
  for (int n = 0; n < header_end; ++n) {
    const std::string_view line = text::trim(lines[static_cast<std::size_t>(n)]);
    const auto colon = line.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string key = ascii_lower(text::trim(line.substr(0, colon)));
    const auto values = text::split(line.substr(colon + 1), " \t", true);
    if (key == "dimension" && !values.empty()) {
      dimension = static_cast<int>(text::parse_double(values[0]).value_or(0));
      line_of_dimension = n + 1;
    } else if (key == "particles" && !values.empty()) {
      count = static_cast<long>(text::parse_double(values[0]).value_or(-1));
      line_of_count = n + 1;
    } else if (key == "phase_id" || key == "diameter" || key == "density" || key == "velocity") {
      V2Option& o = key == "phase_id" ? phase : key == "diameter" ? diameter : key == "density" ? density : velocity;
      o.line = n + 1;
      o.read = !values.empty() && (values[0] == "T" || values[0] == "t");
      for (std::size_t i = 1; i < values.size() && !o.read; ++i)
        if (auto x = text::parse_double(values[i], true)) o.defaults.push_back(*x);
    }
  }
  if (dimension != 3)
    problems.add(text::at_line(path, line_of_dimension > 0 ? line_of_dimension : 1),
                 "only 3-D particle files are supported (Dimension: 3)");
  if (count < 0) problems.add(text::at_line(path, line_of_count > 0 ? line_of_count : 1), "no 'Particles:' count in the header");
  if (!diameter.read && (diameter.defaults.empty() || !(diameter.defaults[0] > 0)))
    problems.add(text::at_line(path, diameter.line > 0 ? diameter.line : 1),
                 "Diameter is not read from the data, so it needs a positive default value");
  problems.throw_if_any();

  // Column layout: x y z [phase] [diameter] [density] [u v w] [...ignored].
  int next = 3;
  const int phase_col = phase.read ? next++ : -1;
  const int diameter_col = diameter.read ? next++ : -1;
  const int density_col = density.read ? next++ : -1;
  const int velocity_col = velocity.read ? next : -1;
  if (velocity.read) next += 3;
  (void)phase_col;
  (void)density_col;

  ParticleSet set;
  set.source = path.string();
  set.has_velocity = velocity.read || std::any_of(velocity.defaults.begin(), velocity.defaults.end(), [](double x) { return x != 0; });
  std::size_t n = static_cast<std::size_t>(kV2DataLine - 1);
  while (static_cast<long>(set.particles.size()) < count && problems.problems().size() < 20) {
    if (n >= lines.size()) {
      problems.add(text::at_line(path, static_cast<int>(lines.size())),
                   "the file ends after " + std::to_string(set.particles.size()) + " of " + std::to_string(count) + " particles");
      break;
    }
    const int line_no = static_cast<int>(n) + 1;
    const auto fields = text::split(lines[n++], " \t,", true);
    if (fields.empty()) continue;
    if (static_cast<int>(fields.size()) < next) {
      problems.add(text::at_line(path, line_no),
                   "expected at least " + std::to_string(next) + " columns, got " + std::to_string(fields.size()));
      continue;
    }
    std::vector<double> v(static_cast<std::size_t>(next));
    bool ok = true;
    for (int i = 0; i < next && ok; ++i) {
      const auto x = text::parse_double(fields[static_cast<std::size_t>(i)], true);
      if (!x) {
        problems.add(text::at_line(path, line_no), std::string("column ").append(std::to_string(i + 1)).append(": '")
                                                       .append(fields[static_cast<std::size_t>(i)]).append("' is not a finite number"));
        ok = false;
      } else {
        v[static_cast<std::size_t>(i)] = *x;
      }
    }
    if (!ok) continue;
    Particle p{v[0], v[1], v[2], diameter_col >= 0 ? v[static_cast<std::size_t>(diameter_col)] : diameter.defaults[0], 0, 0, 0};
    if (!(p.d > 0)) {
      problems.add(text::at_line(path, line_no), "the diameter must be > 0");
      continue;
    }
    if (velocity_col >= 0) {
      p.u = v[static_cast<std::size_t>(velocity_col)];
      p.v = v[static_cast<std::size_t>(velocity_col) + 1];
      p.w = v[static_cast<std::size_t>(velocity_col) + 2];
    } else if (velocity.defaults.size() >= 3) {
      p.u = velocity.defaults[0];
      p.v = velocity.defaults[1];
      p.w = velocity.defaults[2];
    }
    set.particles.push_back(p);
    set.source_lines.push_back(line_no);
  }
  problems.throw_if_any();
  return set;
}

}  // namespace

ParticleSet read_mfix(const std::filesystem::path& path) {
  const std::vector<std::string> lines = text::read_lines(path);
  if (!lines.empty() && text::trim(lines[0]).substr(0, 11) == "Version 2.0") return read_v2(path, lines);
  return read_v1(path, lines);
}

void write_mfix(const std::filesystem::path& path, const ParticleSet& set, double density_g_cm3) {
  std::FILE* f = std::fopen(path.string().c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  for (const Particle& p : set.particles)
    std::fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.x, p.y, p.z, 0.5 * p.d, density_g_cm3,
                 p.u, p.v, p.w);
  const bool failed = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || failed) throw std::runtime_error("error while writing " + path.string());
}

}  // namespace gridfree
