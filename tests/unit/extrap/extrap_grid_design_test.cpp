// SPDX-License-Identifier: GPL-3.0-or-later
// Grid-design warnings of validate/plan (extrap/grid_design.h): the
// degrees-of-freedom rule and the all-coarse rule, each at its boundary.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/grid_design.h"

namespace gridfree {
namespace {

bool has(const std::vector<std::string>& w, const std::string& text) {
  for (const auto& s : w)
    if (s.find(text) != std::string::npos) return true;
  return false;
}

TEST(ExtrapGridDesign, FiveGridsInTheAsymptoticRangeGiveNoWarning) {
  EXPECT_TRUE(grid_design_warnings({2.0, 1.333, 1.0, 0.8, 0.667}).empty());
}

TEST(ExtrapGridDesign, FourGridsLeaveOneDegreeOfFreedom) {
  const auto w = grid_design_warnings({2.0, 1.5, 1.0, 0.5});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(has(w, "4 grid(s) leave 1 degree(s) of freedom"));
  EXPECT_TRUE(has(grid_design_warnings({1.0}), "leave 0 degree(s)"));
}

TEST(ExtrapGridDesign, AllGridsCoarserThanTheThresholdWarn) {
  // The coarse study: Δ* 4 → 2 is not all coarser than 2 (the edge counts as inside) …
  EXPECT_FALSE(has(grid_design_warnings({4, 3.5, 3, 2.5, 2}), "coarser than"));
  // … but 4 → 2.01 is.
  const auto w = grid_design_warnings({4, 3.5, 3, 2.5, 2.01});
  EXPECT_TRUE(has(w, "every grid is coarser than Δ* = 2 (finest 2.01)"));
}

}  // namespace
}  // namespace gridfree
