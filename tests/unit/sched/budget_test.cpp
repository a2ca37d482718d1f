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

// Cores (study/job_cores.h) packed like memory: the cores of the running
// jobs plus the job's own never exceed the pool's; a job needing them all
// runs alone.
TEST(Budget, TwoOneCoreJobsRunTogetherOnTwoCoresAndATwoCoreJobAlone) {
  const BudgetPolicy p{10 * kGiB, 2, 2, 2};  // -j 2 on 2 cores; memory never binds here
  HeadReservation r;
  const std::vector<QueuedJob> ones = {{1, 1 * kGiB, 1}, {2, 1 * kGiB, 1}};
  auto pick = pick_next_job(ones, {}, p, r);
  ASSERT_TRUE(pick);
  const std::vector<QueuedJob> second = {ones[1]};
  pick = pick_next_job(second, {1 * kGiB, 1, 1}, p, r);  // one 1-core job runs: the second fits
  ASSERT_TRUE(pick);
  EXPECT_EQ(second[*pick].job_id, 2);
  // A 2-core job waits while a 1-core job runs (nothing smaller to backfill)...
  const std::vector<QueuedJob> two = {{3, 2 * kGiB, 2}};
  EXPECT_FALSE(pick_next_job(two, {1 * kGiB, 1, 1}, p, r));
  // ...starts on an idle pool, and nothing starts beside it.
  pick = pick_next_job(two, {}, p, r);
  ASSERT_TRUE(pick);
  EXPECT_FALSE(pick_next_job(ones, {2 * kGiB, 1, 2}, p, r));
  // A job needing more cores than the pool has runs alone too.
  const std::vector<QueuedJob> four = {{4, 1 * kGiB, 4}};
  EXPECT_TRUE(pick_next_job(four, {}, p, r));
  EXPECT_FALSE(pick_next_job(four, {1 * kGiB, 1, 1}, p, r));
}

TEST(Budget, CoresBackfillPastAWaitingHead) {
  // 4 cores; a 3-core job runs; the head (largest memory) needs 2 cores and
  // waits; a 1-core job fits beside it and is started past the head.
  const BudgetPolicy p{100 * kGiB, 4, 1, 4};
  HeadReservation r;
  const std::vector<QueuedJob> q = {{1, 8 * kGiB, 2}, {2, 1 * kGiB, 1}};
  const auto pick = pick_next_job(q, {8 * kGiB, 1, 3}, p, r);
  ASSERT_TRUE(pick);
  EXPECT_EQ(q[*pick].job_id, 2);
  EXPECT_EQ(r.skips, 1);
  // Without a core count (Slurm places the jobs) only memory and -j count.
  const BudgetPolicy slurm{0, 4, 1, 0};
  HeadReservation r2;
  const auto any = pick_next_job(q, {0, 1, 3}, slurm, r2);
  ASSERT_TRUE(any);
  EXPECT_EQ(q[*any].job_id, 1);
}

}  // namespace
}  // namespace gridfree
