// SPDX-License-Identifier: GPL-3.0-or-later
// LAMMPS / LIGGGHTS text dump files (particles/particle_io.h).
//
// A dump holds one or more snapshots, each
//
//   ITEM: TIMESTEP                    one integer
//   ITEM: NUMBER OF ATOMS             one integer N
//   ITEM: BOX BOUNDS pp ff pp         three lines "lo hi" (x, y, z)
//   ITEM: ATOMS id type x y z radius vx vy vz ...   then N lines
//
// The ATOMS header names the columns. Positions come from x y z (or the
// unwrapped xu yu zu, or xs ys zs scaled by the box); the size from
// `radius` or `diameter`; velocities from vx vy vz when all three are there.
// Other columns are ignored. A position is moved so that the box's low
// corner is the origin of the case's domain, then lengths (and velocities)
// are converted to cm by the unit system the user names (`si`: ×100, `cgs`:
// ×1). Triclinic boxes ("BOX BOUNDS xy xz yz pp pp pp") are refused.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "particles/particle_io.h"
#include "particles/text_fields.h"

namespace gridfree {
namespace {

struct Columns {
  std::array<int, 3> pos{-1, -1, -1};
  bool scaled = false;     // xs ys zs: fractions of the box
  int size = -1;
  bool radius = false;     // the size column holds radii
  std::array<int, 3> vel{-1, -1, -1};
  std::size_t width = 0;
};

std::optional<Columns> parse_atoms_header(std::string_view header, std::string& why) {
  const auto names = text::split(header, " \t", true);
  Columns c;
  c.width = names.size();
  const std::array<std::array<const char*, 3>, 3> position_names{{{"x", "y", "z"}, {"xu", "yu", "zu"}, {"xs", "ys", "zs"}}};
  const std::array<const char*, 3> velocity_names{"vx", "vy", "vz"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int col = static_cast<int>(i);
    for (std::size_t kind = 0; kind < position_names.size(); ++kind)
      for (int a = 0; a < 3; ++a)
        if (names[i] == position_names[kind][std::size_t(a)] && c.pos[std::size_t(a)] < 0) {
          c.pos[std::size_t(a)] = col;
          if (kind == 2) c.scaled = true;
        }
    for (int a = 0; a < 3; ++a)
      if (names[i] == velocity_names[std::size_t(a)]) c.vel[std::size_t(a)] = col;
    if (names[i] == "radius" || names[i] == "diameter") {
      c.size = col;
      c.radius = names[i] == "radius";
    }
  }
  if (c.pos[0] < 0 || c.pos[1] < 0 || c.pos[2] < 0) {
    why = "the ATOMS columns lack positions (x y z, xu yu zu or xs ys zs)";
    return std::nullopt;
  }
  if (c.size < 0) {
    why = "the ATOMS columns lack the particle size (radius or diameter)";
    return std::nullopt;
  }
  const int velocities = (c.vel[0] >= 0) + (c.vel[1] >= 0) + (c.vel[2] >= 0);
  if (velocities != 0 && velocities != 3) {
    why = "give all of vx vy vz or none";
    return std::nullopt;
  }
  return c;
}

// Reads the snapshots in turn; keeps the one asked for (or the last).
class DumpReader {
 public:
  DumpReader(const std::filesystem::path& path, const LammpsOptions& options)
      : path_(path), options_(options), lines_(text::read_lines(path)) {}

  ParticleSet read() {
    std::optional<ParticleSet> chosen;
    std::vector<std::int64_t> seen;
    while (next_nonblank()) {
      const Snapshot s = snapshot();
      seen.push_back(s.timestep);
      if (!options_.timestep || *options_.timestep == s.timestep) chosen = std::move(s.set);
      if (options_.timestep && *options_.timestep == s.timestep) break;
    }
    if (seen.empty()) throw InputError(path_.string(), "no snapshot in the file (expected 'ITEM: TIMESTEP')");
    if (!chosen) {
      std::string list;
      for (std::size_t i = 0; i < seen.size() && i < 5; ++i) list += (i ? ", " : "") + std::to_string(seen[i]);
      if (seen.size() > 5) list += ", ...";
      throw InputError(path_.string(), "no snapshot at timestep " + std::to_string(*options_.timestep) +
                                           " (the file has " + list + ")");
    }
    return std::move(*chosen);
  }

 private:
  struct Snapshot {
    std::int64_t timestep = 0;
    ParticleSet set;
  };

  // An error at the line read last.
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(text::at_line(path_, static_cast<int>(last_) + 1), why);
  }
  bool next_nonblank() {
    while (at_ < lines_.size() && text::trim(lines_[at_]).empty()) ++at_;
    return at_ < lines_.size();
  }
  // The current line must start with "ITEM: <item>"; returns what follows.
  std::string_view item(std::string_view name) {
    if (!next_nonblank()) fail("the file ends where 'ITEM: " + std::string(name) + "' was expected");
    last_ = at_;
    const std::string_view line = text::trim(lines_[at_]);
    const std::string prefix = "ITEM: " + std::string(name);
    if (line.substr(0, prefix.size()) != prefix) fail("expected 'ITEM: " + std::string(name) + "'");
    ++at_;
    return text::trim(line.substr(prefix.size()));
  }
  std::vector<std::string_view> data_line(const char* what) {
    if (at_ >= lines_.size()) fail(std::string("the file ends where ") + what + " was expected");
    last_ = at_++;
    return text::split(lines_[last_], " \t", true);
  }
  double number(std::string_view field, const char* what) {
    const auto x = text::parse_double(field);
    if (!x) fail(std::string(what) + ": '" + std::string(field.substr(0, 40)) + "' is not a finite number");
    return *x;
  }
  std::int64_t count(const char* what) {
    const auto f = data_line(what);
    const double x = f.size() == 1 ? number(f[0], what) : -1;
    if (f.size() != 1 || x < 0 || x > 1e9 || x != static_cast<double>(static_cast<std::int64_t>(x)))
      fail(std::string(what) + " must be one whole number in [0, 1e9]");
    return static_cast<std::int64_t>(x);
  }

  Snapshot snapshot() {
    Snapshot s;
    item("TIMESTEP");
    s.timestep = count("the timestep");
    item("NUMBER OF ATOMS");
    const std::int64_t n = count("the number of atoms");
    const std::string_view bounds = item("BOX BOUNDS");
    if (bounds.find("xy") != std::string_view::npos) fail("triclinic boxes are not supported");
    std::array<double, 3> lo{}, extent{};
    for (int a = 0; a < 3; ++a) {
      const auto f = data_line("a box bound line 'lo hi'");
      if (f.size() < 2) fail("a box bound line needs 'lo hi'");
      lo[std::size_t(a)] = number(f[0], "box bound");
      const double hi = number(f[1], "box bound");
      extent[std::size_t(a)] = hi - lo[std::size_t(a)];
      if (!(extent[std::size_t(a)] > 0)) fail("the box bound hi must exceed lo");
    }
    std::string why;
    const auto cols = parse_atoms_header(item("ATOMS"), why);
    if (!cols) fail(why);
    const double cm = options_.length_unit_cm;
    s.set.source = path_.string();
    s.set.has_velocity = cols->vel[0] >= 0;
    s.set.particles.reserve(std::min(static_cast<std::size_t>(n), lines_.size() - at_));  // n is bounded by the file
    for (std::int64_t i = 0; i < n; ++i) {
      const auto f = data_line("an atom line");
      const int line_no = static_cast<int>(last_) + 1;
      if (f.size() != cols->width) {
        fail("expected " + std::to_string(cols->width) + " columns, got " + std::to_string(f.size()));
      }
      auto col = [&](int c, const char* what) { return number(f[std::size_t(c)], what); };
      Particle p;
      std::array<double, 3> x{};
      for (int a = 0; a < 3; ++a) {
        const double v = col(cols->pos[std::size_t(a)], "position");
        x[std::size_t(a)] = cols->scaled ? v * extent[std::size_t(a)] : v - lo[std::size_t(a)];
      }
      p.x = x[0] * cm, p.y = x[1] * cm, p.z = x[2] * cm;
      p.d = col(cols->size, "size") * (cols->radius ? 2.0 : 1.0) * cm;
      if (!(p.d > 0)) fail("the particle size must be > 0");
      if (s.set.has_velocity) {
        p.u = col(cols->vel[0], "velocity") * cm;
        p.v = col(cols->vel[1], "velocity") * cm;
        p.w = col(cols->vel[2], "velocity") * cm;
      }
      s.set.particles.push_back(p);
      s.set.source_lines.push_back(line_no);
    }
    s.set.box_cm = {extent[0] * cm, extent[1] * cm, extent[2] * cm};
    return s;
  }

  std::filesystem::path path_;
  LammpsOptions options_;
  std::vector<std::string> lines_;
  std::size_t at_ = 0;    // index of the next line to read
  std::size_t last_ = 0;  // index of the line read last (for messages)
};

}  // namespace

ParticleSet read_lammps_dump(const std::filesystem::path& path, const LammpsOptions& options) {
  return DumpReader(path, options).read();
}

}  // namespace gridfree
