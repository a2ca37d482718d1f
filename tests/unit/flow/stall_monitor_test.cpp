// SPDX-License-Identifier: GPL-3.0-or-later
// The stall test of the nested start's coarse levels (flow/stall_monitor.h).
#include "flow/stall_monitor.h"

#include <cmath>

#include <gtest/gtest.h>

namespace gridfree {
namespace {

// The slowest converging coarse level measured: 4 decades in 397 outer
// iterations, a halving every ≈ 30. It never stalls, even with a 30 %
// iteration-to-iteration wobble on top.
TEST(StallMonitor, AConvergingLoopNeverStalls) {
  StallMonitor m(100);
  for (int it = 0; it < 2000; ++it) {
    const double r = 1e-1 * std::pow(1e-4, it / 397.0) * (1 + 0.3 * ((it % 2) ? 1 : -1));
    ASSERT_FALSE(m.stalled(r)) << "iteration " << it + 1;
  }
}

// A residual that stays put stalls once a whole window has passed without
// halving the best value before it: at iteration window + 1.
TEST(StallMonitor, AConstantResidualStallsAfterOneWindow) {
  StallMonitor m(100);
  for (int it = 1; it <= 100; ++it) ASSERT_FALSE(m.stalled(2e-5)) << it;
  EXPECT_TRUE(m.stalled(2e-5));
}

// The limit cycle of an SSCP-like coarse level (8 × 40 × 3 cells): the
// residual falls to ≈ 2e-5 in 100 iterations, then oscillates between 1e-5
// and 3e-5. It stalls within two windows of reaching the cycle.
TEST(StallMonitor, ALimitCycleStallsWithinTwoWindows) {
  StallMonitor m(100);
  int stalled_at = 0;
  for (int it = 1; it <= 1000 && stalled_at == 0; ++it) {
    const double r = it <= 100 ? 1e-1 * std::pow(2e-4, it / 100.0) : 2e-5 + 1e-5 * std::sin(0.7 * it);
    if (m.stalled(r)) stalled_at = it;
  }
  EXPECT_GT(stalled_at, 100);
  EXPECT_LE(stalled_at, 300);
}

// Still halving over each window: not stalled, however slowly it goes.
TEST(StallMonitor, HalvingOncePerWindowIsProgress) {
  StallMonitor m(10);
  for (int it = 0; it < 200; ++it) ASSERT_FALSE(m.stalled(std::pow(0.5, it / 9.0))) << it;
}

}  // namespace
}  // namespace gridfree
