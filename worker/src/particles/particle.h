// SPDX-License-Identifier: GPL-3.0-or-later
// A frozen particle: centre (cm), diameter (cm), velocity (cm/s).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct Particle {
  double x = 0, y = 0, z = 0;  // centre, cm
  double d = 0;                // diameter, cm
  double u = 0, v = 0, w = 0;  // velocity, cm/s (zero for a frozen bed)
};

struct ParticleSet {
  std::vector<Particle> particles;
  bool has_velocity = false;  // true when velocities were given or generated
  // Provenance for messages: the file the set was read from (empty when
  // generated) and, per particle, its 1-based line in that file.
  std::string source;
  std::vector<int> source_lines;
  // The simulation box's edge lengths (cm) when the file states one (LAMMPS dumps).
  std::optional<std::array<double, 3>> box_cm;
};

}  // namespace gridfree
