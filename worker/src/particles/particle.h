// A frozen particle: centre (cm), diameter (cm), velocity (cm/s).
#pragma once

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
};

}  // namespace gridfree
