// SPDX-License-Identifier: GPL-3.0-or-later
// The fictitious bursting bubble of Fullmer & Musser (2018) §3, as this
// project reconstructs it (PHYSICS.md §6). In particle diameters (d = the
// case's particle diameter, domain from the case):
//
//   dense bed   y* < 28, minus the bubble      ε_s = 0.30
//   bubble      |x* − (15, 22, 5)| < 5          ε_s = 0.01
//   freeboard   28 ≤ y* < 50                    ε_s = 0.01
//   above       y* ≥ 50                         empty
//
// N_region = round(ε_s · V_region / V_p) with exact volumes (the sphere lies
// inside the dense box, so V_dense = L_x·28·L_z − 4/3 π 5³, all times d³).
// Regions are filled in that order by random sequential addition; a
// particle belongs to the region holding its centre. On the paper's domain
// 30 × 200 × 10 this gives 4513 + 10 + 126 = 4649 particles.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "particles/generator_params.h"
#include "particles/sphere_packer.h"

namespace gridfree {
namespace {

constexpr double kDenseTop = 28, kFreeboardTop = 50;          // y*, particle diameters
constexpr double kDenseFraction = 0.30, kDiluteFraction = 0.01;
constexpr double kBubbleRadius = 5;
constexpr std::array<double, 3> kBubbleCentre{15, 22, 5};

void require_all_placed(std::size_t placed, std::size_t wanted, const char* region, const std::string& where) {
  if (placed < wanted)
    throw InputError(where, "random sequential addition stalled in the " + std::string(region) + " region after " +
                                std::to_string(placed) + " of " + std::to_string(wanted) + " particles");
}

}  // namespace

GeneratedParticles generate_bursting_bubble(const BurstingBubbleParams& p, const CaseSpec& c, const std::string& where) {
  const double d = c.particle_diameter_cm;
  const Vec3 L = c.domain_cm();
  const double vp = particle_volume(d);
  SpherePacker packer(L, periodic_axes(c), d);
  ParticleRandom rng(p.seed);

  const double y_dense = std::min(kDenseTop * d, L[1]);
  const double y_free = std::min(kFreeboardTop * d, L[1]);
  const double radius = kBubbleRadius * d;
  const Vec3 centre{kBubbleCentre[0] * d, kBubbleCentre[1] * d, kBubbleCentre[2] * d};
  const double v_sphere = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double v_dense = L[0] * y_dense * L[2] - v_sphere;
  const double v_free = L[0] * (y_free - y_dense) * L[2];
  const auto count = [vp](double fraction, double volume) {
    return static_cast<std::size_t>(std::llround(fraction * volume / vp));
  };
  const std::size_t n_dense = count(kDenseFraction, v_dense);
  const std::size_t n_bubble = count(kDiluteFraction, v_sphere);
  const std::size_t n_free = count(kDiluteFraction, v_free);
  const auto in_bubble = [&](const Vec3& x) {
    return packer.cells().distance_squared(x, centre) < radius * radius;
  };
  const auto anywhere = [](const Vec3&) { return true; };
  const auto slab = [&](double y0, double y1) { return Box{{0, y0, 0}, {L[0], y1, L[2]}}; };

  // Dense bed: the slab y < 28 d outside the bubble.
  std::size_t placed = packer.add_random(n_dense, rng, slab(0, y_dense), [&](const Vec3& x) { return !in_bubble(x); });
  require_all_placed(placed, n_dense, "dense", where);

  // Bubble: uniform in the sphere (its bounding cube, minus the corners).
  const Box cube{{centre[0] - radius, centre[1] - radius, centre[2] - radius},
                 {centre[0] + radius, centre[1] + radius, centre[2] + radius}};
  placed = packer.add_random(n_bubble, rng, cube, in_bubble);
  require_all_placed(placed, n_bubble, "bubble", where);

  // Freeboard: 28 d <= y < 50 d.
  placed = packer.add_random(n_free, rng, slab(y_dense, y_free), anywhere);
  require_all_placed(placed, n_free, "freeboard", where);

  GeneratedParticles out;
  out.set.particles.reserve(packer.centres().size());
  for (const Vec3& x : packer.centres()) out.set.particles.push_back({x[0], x[1], x[2], d, 0, 0, 0});
  out.regions.push_back(make_report("dense", v_dense, kDenseFraction, n_dense, d));
  out.regions.push_back(make_report("bubble", v_sphere, kDiluteFraction, n_bubble, d));
  out.regions.push_back(make_report("freeboard", v_free, kDiluteFraction, n_free, d));
  out.regions.push_back(make_report("above freeboard", L[0] * (L[1] - y_free) * L[2], 0.0, 0, d));
  return out;
}

}  // namespace gridfree
