// SPDX-License-Identifier: GPL-3.0-or-later
// uniform_random: the count is round(ε_s V / V_p), the particles stay in the
// box, never overlap (O(N²) check), and fractions RSA cannot reach are
// refused up front, naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particle_checks.h"
#include "particles/generators.h"

namespace gridfree {
namespace {

CaseSpec box_case(bool periodic_xz) {
  CaseSpec c;
  c.domain_dp = {12, 16, 10};
  c.particle_diameter_cm = 0.02;
  const BoundarySpec side{periodic_xz ? BoundaryKind::kPeriodic : BoundaryKind::kWall, 0, 0};
  c.boundaries[0] = {side, side};
  c.boundaries[2] = {side, side};
  c.boundaries[1] = {BoundarySpec{BoundaryKind::kMassInflow, 1, 0}, BoundarySpec{BoundaryKind::kPressureOutflow, 0, 0}};
  return c;
}

GeneratorSpec uniform(double fraction, nlohmann::json region = nullptr) {
  nlohmann::json j = {{"kind", "uniform_random"}, {"seed", 5}, {"solids_fraction", fraction}};
  if (!region.is_null()) j["region_dp"] = region;
  return {"uniform_random", j, "/case/particles/generator"};
}

TEST(UniformRandomGenerator, FractionOverTheWholeDomain) {
  for (bool periodic : {true, false}) {
    const CaseSpec c = box_case(periodic);
    const GeneratedParticles out = generate_particles_with_report(uniform(0.35), c);
    const double volume_dp = 12 * 16 * 10, vp_dp = std::numbers::pi / 6;
    EXPECT_EQ(out.set.particles.size(), static_cast<std::size_t>(std::lround(0.35 * volume_dp / vp_dp)));
    // One particle is V_p/V = 0.027 % of the fraction: 0.005 is generous.
    EXPECT_NEAR(out.set.particles.size() * vp_dp / volume_dp, 0.35, 0.005);
    EXPECT_EQ(test::count_overlaps(out.set.particles, c.domain_cm(), {periodic, false, periodic}), 0u);
    EXPECT_EQ(test::count_outside(out.set.particles, c.domain_cm(), {periodic, false, periodic}), 0u);
  }
}

TEST(UniformRandomGenerator, RegionBox) {
  const CaseSpec c = box_case(true);
  const nlohmann::json region = {{"min", {0, 2, 0}}, {"max", {12, 8, 10}}};
  const ParticleSet set = generate_particles(uniform(0.2, region), c);
  EXPECT_EQ(set.particles.size(), static_cast<std::size_t>(std::lround(0.2 * 12 * 6 * 10 / (std::numbers::pi / 6))));
  for (const Particle& p : set.particles) {
    EXPECT_GE(p.y, 2 * 0.02);
    EXPECT_LT(p.y, 8 * 0.02);
  }
}

TEST(UniformRandomGenerator, UnreachableFractionNamesTheField) {
  try {
    generate_particles(uniform(0.45), box_case(true));
    FAIL() << "accepted a fraction beyond random sequential addition";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].where, "/case/particles/generator/solids_fraction");
  }
}

}  // namespace
}  // namespace gridfree
