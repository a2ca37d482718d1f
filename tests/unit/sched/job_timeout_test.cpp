// SPDX-License-Identifier: GPL-3.0-or-later
// The default per-job timeout (sched/job_timeout.h): the floor for small
// grids, the stated multiple of the plan's estimate for large ones.
#include <gtest/gtest.h>

#include "sched/job_timeout.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

TEST(JobTimeout, SmallGridsGetTheFloor) {
  EXPECT_DOUBLE_EQ(default_job_timeout_s({30, 200, 10}, 1), kMinJobTimeoutS);
}

TEST(JobTimeout, LargeGridsGetTheMarginTimesTheEstimate) {
  const std::array<int, 3> cells = {600, 4000, 200};  // 4.8e8 cells
  const double estimate = estimated_seconds(cells, 2);
  ASSERT_GT(kJobTimeoutMargin * estimate, kMinJobTimeoutS);
  EXPECT_DOUBLE_EQ(default_job_timeout_s(cells, 2), kJobTimeoutMargin * estimate);
  EXPECT_GT(default_job_timeout_s(cells, 1), default_job_timeout_s(cells, 2));  // fewer threads, longer
}

}  // namespace
}  // namespace gridfree
