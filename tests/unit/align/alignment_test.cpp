// SPDX-License-Identifier: GPL-3.0-or-later
// The alignment check's pieces (align/alignment.h): the variant product,
// the particle shift (wrap on periodic axes, refusal out of a bounded
// domain), and the spread rule (max − min)/mean only when every variant
// converged.
#include <gtest/gtest.h>

#include "align/alignment.h"
#include "core/input_error.h"

namespace gridfree {
namespace {

TEST(Alignment, VariantsAreEveryCombination) {
  const auto v = alignment_variants({std::vector<int>{}, std::vector<int>{0, 1, 2}, std::vector<int>{0, 1}}, {0.0, 0.5}, 1);
  EXPECT_EQ(v.size(), 12u);  // 3 n_y × 2 n_z × 2 shifts (empty n_x counts as {0})
  EXPECT_EQ(v.back().cell_offsets, (std::array<int, 3>{0, 2, 1}));
  EXPECT_DOUBLE_EQ(v.back().shift_fraction, 0.5);
}

TEST(Alignment, ShiftWrapsPeriodicAxesAndRefusesLeavingAWalledOne) {
  Grid g;
  g.n = {4, 10, 1};
  g.length = {0.4, 1.0, 0.1};
  g.periodic = {true, false, true};
  ParticleSet set;
  set.particles = {{0.39, 0.5, 0.05, 0.01}};
  const ParticleSet x = shifted_particles(set, g, 0, 0.5);  // Δx = 0.1: 0.39 + 0.05 → 0.04
  EXPECT_NEAR(x.particles[0].x, 0.04, 1e-15);
  const ParticleSet y = shifted_particles(set, g, 1, 0.25);
  EXPECT_NEAR(y.particles[0].y, 0.525, 1e-15);
  set.particles[0].y = 0.99;
  EXPECT_THROW(shifted_particles(set, g, 1, 0.5), InputError);
}

TEST(Alignment, SpreadOnlyWhenEveryVariantConverged) {
  AlignReport r;
  for (double dp : {1000.0, 1010.0, 1005.0}) {
    AlignVariantResult v;
    v.status = SolveStatus::kConverged;
    v.dp_star = dp;
    r.variants.push_back(v);
  }
  summarise_alignment(r);
  ASSERT_TRUE(r.spread.has_value());
  EXPECT_NEAR(*r.spread, 10.0 / 1005.0, 1e-15);
  r.variants[1].status = SolveStatus::kNotConverged;
  r.spread.reset();
  summarise_alignment(r);
  EXPECT_FALSE(r.spread.has_value());
  EXPECT_FALSE(r.reason.empty());
}

}  // namespace
}  // namespace gridfree
