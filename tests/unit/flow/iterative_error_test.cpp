// SPDX-License-Identifier: GPL-3.0-or-later
// The geometric iterative-error estimate: exact on q_n = q_∞ + C ρ^n
// (monotone and alternating), absent where it cannot be trusted.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/iterative_error.h"

namespace gridfree {
namespace {

std::deque<double> geometric(double q_inf, double c, double rho, int first, int count) {
  std::deque<double> h;
  for (int n = first; n < first + count; ++n) h.push_back(q_inf + c * std::pow(rho, n));
  return h;
}

TEST(IterativeError, ExactForAGeometricSequence) {
  for (double rho : {0.5, 0.9, 0.99, -0.7}) {
    const int window = rho < 0 ? 4 : 10;  // an even window sees an alternating sequence shrink
    const auto h = geometric(1000.0, 3.0, rho, 5, 2 * window + 1);
    const auto e = geometric_iterative_error(h, window);
    ASSERT_TRUE(e.has_value()) << rho;
    const double truth = std::abs(h.back() - 1000.0) / std::abs(h.back());
    EXPECT_NEAR(*e / truth, 1.0, 1e-8) << "rho " << rho;
  }
}

TEST(IterativeError, AbsentWhenItCannotBeEstimated) {
  EXPECT_FALSE(geometric_iterative_error(geometric(1, 1, 0.5, 0, 20), 10).has_value());  // too short
  EXPECT_FALSE(geometric_iterative_error(geometric(1, 1, 1.1, 0, 21), 10).has_value());  // growing
  std::deque<double> stalled(21, 5.0);
  stalled[0] = 4.0;  // changed once, then flat: last change 0 → error 0
  EXPECT_EQ(geometric_iterative_error(stalled, 10).value(), 0.0);
  std::deque<double> zero = geometric(0.0, 1.0, 0.5, 0, 21);
  zero.back() = 0.0;
  EXPECT_FALSE(geometric_iterative_error(zero, 10).has_value());  // no relative scale
}

}  // namespace
}  // namespace gridfree
