// SPDX-License-Identifier: GPL-3.0-or-later
// sscp_like on a small bed with walls in x and z: the emulsion holds its
// target fraction (counted from the particle centres here), bubbles are
// dilute, nothing overlaps (O(N²)), nothing crosses a wall or the bed top,
// and the same seed gives the same bed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particle_checks.h"
#include "particles/generators.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

using test_support::sscp_bed_case;

GeneratorSpec sscp(std::uint64_t seed, int bubbles) {
  return {"sscp_like",
          {{"kind", "sscp_like"}, {"seed", seed}, {"bed_height_dp", 20}, {"solids_fraction", 0.58},
           {"bubbles", bubbles}, {"bubble_radius_dp", 3}},
          "/generator"};
}

TEST(SscpLikeGenerator, EmulsionFractionAndNoOverlap) {
  const CaseSpec c = sscp_bed_case();
  const GeneratedParticles out = generate_particles_with_report(sscp(1, 2), c);
  const auto& regions = out.regions;
  ASSERT_GE(regions.size(), 2u);
  EXPECT_EQ(regions[0].name, "emulsion");
  // 2 bubbles of radius 3 d: V = 2 · 4/3 π 27 d³; emulsion = bed − bubbles.
  const double vp = std::numbers::pi / 6, v_bubbles = 2 * 4.0 / 3.0 * std::numbers::pi * 27;
  const double v_emulsion = 16 * 20 * 8 - v_bubbles;
  const std::size_t expected_emulsion = static_cast<std::size_t>(std::lround(0.58 * v_emulsion / vp));
  const std::size_t expected_bubble = 2 * static_cast<std::size_t>(std::lround(0.01 * v_bubbles / 2 / vp));
  EXPECT_EQ(out.set.particles.size(), expected_emulsion + expected_bubble);
  // Every centre lies in the bed (y* < 20): the measured bed fraction is
  // (all particles) V_p / V_bed, which must sit between the emulsion and
  // bubble targets and match the mixture to rounding.
  const double d = c.particle_diameter_cm;
  for (const Particle& p : out.set.particles) EXPECT_LE(p.y, 20 * d - 0.5 * d + 1e-12);
  const double mixture = (0.58 * v_emulsion + 0.01 * v_bubbles) / (16 * 20 * 8);
  // One particle is V_p / V_bed = 0.02 % of the fraction: ±0.005 absolute.
  EXPECT_NEAR(out.set.particles.size() * vp / (16 * 20 * 8), mixture, 0.005);
  EXPECT_NEAR(regions[0].solids_fraction, 0.58, 0.005);
  EXPECT_EQ(test::count_overlaps(out.set.particles, c.domain_cm(), {false, false, false}), 0u);
  EXPECT_EQ(test::count_outside(out.set.particles, c.domain_cm(), {false, false, false}), 0u);
}

TEST(SscpLikeGenerator, DeterministicPerSeed) {
  const CaseSpec c = sscp_bed_case();
  const ParticleSet a = generate_particles(sscp(4, 1), c);
  const ParticleSet b = generate_particles(sscp(4, 1), c);
  const ParticleSet other = generate_particles(sscp(5, 1), c);
  ASSERT_EQ(a.particles.size(), b.particles.size());
  bool same = true, differs = false;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    same = same && a.particles[i].x == b.particles[i].x && a.particles[i].y == b.particles[i].y &&
           a.particles[i].z == b.particles[i].z;
    differs = differs || i >= other.particles.size() || a.particles[i].x != other.particles[i].x;
  }
  EXPECT_TRUE(same);
  EXPECT_TRUE(differs);
}

TEST(SscpLikeGenerator, TooDenseIsRefused) {
  GeneratorSpec g = sscp(1, 0);
  g.params["solids_fraction"] = 0.7;
  try {
    generate_particles(g, sscp_bed_case());
    FAIL() << "accepted an emulsion denser than random close packing";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems()[0].where, "/generator/solids_fraction");
  }
}

}  // namespace
}  // namespace gridfree
