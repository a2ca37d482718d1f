// SPDX-License-Identifier: GPL-3.0-or-later
// The optional sscp_like parameters act as documented (docs/PARTICLES.md):
// bubble_solids_fraction sets the number of particles in each bubble,
// round(ε_b V_bubble / V_p); relaxation_sweeps moves the emulsion
// particles of the lattice emulsion (0 sweeps leaves the jittered lattice)
// without changing their number or creating overlaps, and is refused with
// the random emulsion; emulsion takes random or lattice only.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particle_checks.h"
#include "particles/generators.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

using test_support::sscp_bed_case;

GeneratorSpec sscp_with(const nlohmann::json& extra) {
  nlohmann::json p = {{"kind", "sscp_like"}, {"seed", 3},  {"bed_height_dp", 20}, {"solids_fraction", 0.58},
                      {"bubbles", 1},        {"bubble_radius_dp", 4}};
  if (extra.is_object()) p.merge_patch(extra);
  return {"sscp_like", p, "/generator"};
}

TEST(SscpLikeOptions, BubbleSolidsFractionSetsTheBubbleCount) {
  const CaseSpec c = sscp_bed_case();
  const double vp = std::numbers::pi / 6, v_bubble = 4.0 / 3.0 * std::numbers::pi * 64;  // in d³
  const auto dilute = generate_particles(sscp_with({}), c).particles.size();
  const auto denser = generate_particles(sscp_with({{"bubble_solids_fraction", 0.2}}), c).particles.size();
  EXPECT_EQ(denser - dilute, static_cast<std::size_t>(std::lround(0.2 * v_bubble / vp)) -
                                 static_cast<std::size_t>(std::lround(0.01 * v_bubble / vp)));
}

TEST(SscpLikeOptions, RelaxationSweepsMoveParticlesKeepingCountAndNoOverlap) {
  const CaseSpec c = sscp_bed_case();
  const auto none = generate_particles(sscp_with({{"emulsion", "lattice"}, {"relaxation_sweeps", 0}}), c).particles;
  const auto some = generate_particles(sscp_with({{"emulsion", "lattice"}, {"relaxation_sweeps", 20}}), c).particles;
  ASSERT_EQ(none.size(), some.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < none.size(); ++i) moved += none[i].x != some[i].x || none[i].y != some[i].y;
  EXPECT_GT(moved, none.size() / 2);  // sweeps accept 30–50 % of the tries, 20 times
  EXPECT_EQ(test::count_overlaps(some, c.domain_cm(), {false, false, false}), 0u);
  EXPECT_EQ(test::count_overlaps(none, c.domain_cm(), {false, false, false}), 0u);
}

std::string first_problem(const nlohmann::json& extra) {
  try {
    generate_particles(sscp_with(extra), sscp_bed_case());
  } catch (const InputError& e) {
    return e.problems()[0].where + ": " + e.problems()[0].reason;
  }
  return "accepted";
}

TEST(SscpLikeOptions, EmulsionChoicesAndTheirLimits) {
  EXPECT_EQ(first_problem({{"relaxation_sweeps", 5}}).rfind("/generator/relaxation_sweeps: applies only", 0), 0u);
  EXPECT_EQ(first_problem({{"emulsion", "fcc"}}).rfind("/generator/emulsion: 'fcc' is not one of", 0), 0u);
  // 0.605: beyond the random packing's 0.60; the lattice holds it (without
  // the bubble, which takes too many of its sites in this small bed).
  EXPECT_EQ(first_problem({{"solids_fraction", 0.605}}).rfind("/generator/solids_fraction: 0.605 is above 0.6", 0), 0u);
  EXPECT_EQ(first_problem({{"solids_fraction", 0.605}, {"emulsion", "lattice"}, {"bubbles", 0}}), "accepted");
}

}  // namespace
}  // namespace gridfree
