// SPDX-License-Identifier: GPL-3.0-or-later
// A closeness check relative to the size of the expected value.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gridfree::test_support {

// |actual − expected| ≤ tol · max(1, |expected|): relative for values above
// 1, absolute below.
inline void expect_rel(double actual, double expected, double tol) {
  EXPECT_NEAR(actual, expected, tol * std::max(1.0, std::fabs(expected)));
}

}  // namespace gridfree::test_support
