// SPDX-License-Identifier: GPL-3.0-or-later
// Random particle velocities: u, v, w ~ N(0, σ²) per particle, σ = thermal_cm_s.
#include "particles/generators.h"
#include "particles/random.h"

namespace gridfree {

void apply_thermal_velocity(ParticleSet& set, const ParticleVelocitySpec& spec) {
  if (!(spec.thermal_cm_s > 0)) return;
  ParticleRandom rng(spec.seed);
  for (Particle& p : set.particles) {
    p.u = spec.thermal_cm_s * rng.normal();
    p.v = spec.thermal_cm_s * rng.normal();
    p.w = spec.thermal_cm_s * rng.normal();
  }
  set.has_velocity = true;
}

}  // namespace gridfree
