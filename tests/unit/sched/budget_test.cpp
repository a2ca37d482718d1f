// SPDX-License-Identifier: GPL-3.0-or-later
// The budget rule (sched/budget.h) and the memory budget's source
// (sched/memory_budget.h).
#include <gtest/gtest.h>

#include <vector>

#include "core/input_error.h"
#include "sched/budget.h"
#include "sched/memory_budget.h"

namespace gridfree {
namespace {

constexpr double kGiB = 1024.0 * 1024 * 1024;

TEST(Budget, LargestFirstWhenItFits) {
  const std::vector<QueuedJob> q = {{1, 1 * kGiB}, {2, 4 * kGiB}, {3, 2 * kGiB}};
  HeadReservation r;
  const auto pick = pick_next_job(q, {}, {10 * kGiB, 4, 4}, r);
  ASSERT_TRUE(pick);
  EXPECT_EQ(q[*pick].job_id, 2);
}

TEST(Budget, TwoJobsOfSixtyPercentNeverRunTogether) {
  const std::vector<QueuedJob> q = {{1, 6 * kGiB}, {2, 6 * kGiB}};
  HeadReservation r;
  // One runs (6 of 10 GiB): the other does not fit and nothing smaller is queued.
  EXPECT_FALSE(pick_next_job(q, {6 * kGiB, 1}, {10 * kGiB, 4, 4}, r));
}

TEST(Budget, SmallJobsBackfillBesideABigOneUpToTheSkipBound) {
  // Running: 6 GiB. Head: 6 GiB (does not fit); small 1 GiB jobs do.
  std::vector<QueuedJob> q = {{1, 6 * kGiB}, {2, 1 * kGiB}, {3, 1 * kGiB}, {4, 2 * kGiB}};
  HeadReservation r;
  const BudgetPolicy p{10 * kGiB, 8, 2};
  auto pick = pick_next_job(q, {6 * kGiB, 1}, p, r);
  ASSERT_TRUE(pick);
  EXPECT_EQ(q[*pick].job_id, 4);  // the largest that fits
  EXPECT_EQ(r.skips, 1);
  q.erase(q.begin() + static_cast<long>(*pick));
  pick = pick_next_job(q, {8 * kGiB, 2}, p, r);
  ASSERT_TRUE(pick);
  EXPECT_EQ(q[*pick].job_id, 2);
  q.erase(q.begin() + static_cast<long>(*pick));
  // Two jobs started past the head: the rest waits for it, even though a
  // 1 GiB job would fit beside the running ones.
  EXPECT_FALSE(pick_next_job(q, {1 * kGiB + 6 * kGiB, 2}, p, r));
  // Once the head fits it starts and the reservation ends.
  pick = pick_next_job(q, {1 * kGiB, 1}, p, r);
  ASSERT_TRUE(pick);
  EXPECT_EQ(q[*pick].job_id, 1);
  EXPECT_FALSE(r.head);
}

TEST(Budget, JobCountLimitAndNoBudget) {
  const std::vector<QueuedJob> q = {{1, 100 * kGiB}};
  HeadReservation r;
  EXPECT_FALSE(pick_next_job(q, {0, 2}, {0, 2, 2}, r));   // -j 2 reached
  EXPECT_TRUE(pick_next_job(q, {50 * kGiB, 1}, {0, 2, 2}, r));  // no memory budget: only -j counts
}

TEST(Budget, AJobLargerThanTheBudgetRunsAlone) {
  const std::vector<QueuedJob> q = {{1, 12 * kGiB}};
  HeadReservation r;
  EXPECT_TRUE(pick_next_job(q, {}, {10 * kGiB, 4, 4}, r));
  EXPECT_FALSE(pick_next_job(q, {0.1 * kGiB, 1}, {10 * kGiB, 4, 4}, r));
}

TEST(MemoryBudget, ReadsMemAvailableAndTheFlag) {
  const auto b = mem_available_bytes("MemTotal:  16000000 kB\nMemFree: 1000 kB\nMemAvailable:   8000000 kB\n");
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(*b, 8000000.0 * 1024);
  EXPECT_FALSE(mem_available_bytes("MemTotal: 1 kB\n"));
  EXPECT_DOUBLE_EQ(resolve_memory_budget("2G").bytes, 2 * kGiB);
  EXPECT_EQ(resolve_memory_budget("2G").source, "--memory-budget");
  EXPECT_THROW(resolve_memory_budget("lots"), InputError);
  EXPECT_GT(resolve_memory_budget("").bytes, 0.0);
}

}  // namespace
}  // namespace gridfree
