// SPDX-License-Identifier: GPL-3.0-or-later
// A uniform random bed: ε_s = solids_fraction in a box (default: the whole
// domain), N = round(ε_s · V_box / V_p) equal spheres placed by random
// sequential addition with centres uniform in the box (and off the
// non-periodic walls). RSA jams near ε_s ≈ 0.38, hence the 0.38 cap.
#include <algorithm>
#include <cmath>

#include "particles/generator_params.h"
#include "particles/sphere_packer.h"

namespace gridfree {

GeneratedParticles generate_uniform_random(const UniformRandomParams& p, const CaseSpec& c, const std::string& where) {
  const double d = c.particle_diameter_cm;
  const Vec3 L = c.domain_cm();
  SpherePacker packer(L, periodic_axes(c), d);
  ParticleRandom rng(p.seed);

  Box box;
  double volume = 1;
  for (int a = 0; a < 3; ++a) {
    volume *= (p.max_dp[a] - p.min_dp[a]) * d;
    box.lo[a] = p.min_dp[a] * d;
    box.hi[a] = p.max_dp[a] * d;
  }
  const auto wanted = static_cast<std::size_t>(std::llround(p.solids_fraction * volume / particle_volume(d)));
  const std::size_t placed = packer.add_random(wanted, rng, box, [](const Vec3&) { return true; });
  if (placed < wanted)
    throw InputError(where + "/solids_fraction",
                     "random sequential addition stalled after " + std::to_string(placed) + " of " +
                         std::to_string(wanted) + " particles; lower the solids fraction or enlarge the region");

  GeneratedParticles out;
  out.set.particles.reserve(placed);
  for (const Vec3& x : packer.centres()) out.set.particles.push_back({x[0], x[1], x[2], d, 0, 0, 0});
  out.regions.push_back(make_report("region", volume, p.solids_fraction, placed, d));
  const double domain_volume = L[0] * L[1] * L[2];
  if (domain_volume - volume > 1e-12 * domain_volume)
    out.regions.push_back(make_report("outside region", domain_volume - volume, 0.0, 0, d));
  return out;
}

}  // namespace gridfree
