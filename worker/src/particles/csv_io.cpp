// SPDX-License-Identifier: GPL-3.0-or-later
// CSV particle files: x,y,z,d[,u,v,w] (particles/particle_io.h).
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "core/text.h"
#include "particles/particle_io.h"
#include "particles/text_fields.h"

namespace gridfree {
namespace {

constexpr std::array<const char*, 7> kColumns{"x", "y", "z", "d", "u", "v", "w"};

}  // namespace

void write_csv(const std::filesystem::path& path, const ParticleSet& set) {
  std::FILE* f = std::fopen(path.string().c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  std::fputs(set.has_velocity ? "x,y,z,d,u,v,w\n" : "x,y,z,d\n", f);
  for (const Particle& p : set.particles) {
    if (set.has_velocity)
      std::fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.x, p.y, p.z, p.d, p.u, p.v, p.w);
    else
      std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", p.x, p.y, p.z, p.d);
  }
  const bool failed = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || failed) throw std::runtime_error("error while writing " + path.string());
}

ParticleSet read_csv(const std::filesystem::path& path) {
  const std::vector<std::string> lines = text::read_lines(path);
  ParticleSet set;
  set.source = path.string();
  ProblemList problems;
  // column[c] = index of field c (x,y,z,d,u,v,w) in a row, or -1.
  std::array<int, 7> column{-1, -1, -1, -1, -1, -1, -1};
  std::size_t width = 0;
  bool have_layout = false;
  for (std::size_t n = 0; n < lines.size() && problems.problems().size() < 20; ++n) {
    const int line_no = static_cast<int>(n) + 1;
    const std::string_view line = text::trim(lines[n]);
    if (line.empty() || line.front() == '#') continue;
    const auto fields = text::split(line, ",", false);
    if (!have_layout) {
      have_layout = true;
      if (!text::parse_double(fields[0])) {  // a header
        width = fields.size();
        for (std::size_t i = 0; i < fields.size(); ++i) {
          const std::string name = ascii_lower(fields[i]);
          bool known = false;
          for (std::size_t c = 0; c < kColumns.size(); ++c) {
            if (name != kColumns[c]) continue;
            known = true;
            if (column[c] >= 0) problems.add(text::at_line(path, line_no), "column '" + name + "' appears twice");
            column[c] = static_cast<int>(i);
          }
          if (!known) spdlog::warn("{}: ignoring column '{}'", text::at_line(path, line_no), name);
        }
        for (int c = 0; c < 4; ++c)
          if (column[c] < 0)
            problems.add(text::at_line(path, line_no), std::string("the header lacks column '") + kColumns[c] + "' (x,y,z,d are required)");
        const int velocities = (column[4] >= 0) + (column[5] >= 0) + (column[6] >= 0);
        if (velocities != 0 && velocities != 3)
          problems.add(text::at_line(path, line_no), "give all of u,v,w or none");
        set.has_velocity = velocities == 3;
        problems.throw_if_any();
        continue;
      }
      if (fields.size() != 4 && fields.size() != 7) {
        problems.add(text::at_line(path, line_no),
                     "expected 4 columns (x,y,z,d) or 7 (x,y,z,d,u,v,w), got " + std::to_string(fields.size()));
        break;
      }
      width = fields.size();
      for (std::size_t c = 0; c < width; ++c) column[c] = static_cast<int>(c);
      set.has_velocity = width == 7;
    }
    if (fields.size() != width) {
      problems.add(text::at_line(path, line_no),
                   "expected " + std::to_string(width) + " columns, got " + std::to_string(fields.size()));
      continue;
    }
    std::array<double, 7> v{};
    bool ok = true;
    for (std::size_t c = 0; c < kColumns.size() && ok; ++c) {
      if (column[c] < 0) continue;
      const auto x = text::parse_double(fields[static_cast<std::size_t>(column[c])]);
      if (!x) {
        problems.add(text::at_line(path, line_no), std::string("column ") + kColumns[c] + ": '" +
                                                       std::string(fields[static_cast<std::size_t>(column[c])]) +
                                                       "' is not a finite number");
        ok = false;
      } else {
        v[c] = *x;
      }
    }
    if (!ok) continue;
    if (!(v[3] > 0)) {
      problems.add(text::at_line(path, line_no), std::string("the diameter must be > 0, got ").append(fields[static_cast<std::size_t>(column[3])]));
      continue;
    }
    set.particles.push_back({v[0], v[1], v[2], v[3], v[4], v[5], v[6]});
    set.source_lines.push_back(line_no);
  }
  problems.throw_if_any();
  return set;
}

}  // namespace gridfree
