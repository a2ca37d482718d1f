// SPDX-License-Identifier: GPL-3.0-or-later
// ETA from the cost model scaled by measured times (sched/study_eta.h):
// the arithmetic of the header on small hand-checked cases.
#include <gtest/gtest.h>

#include "sched/study_eta.h"

namespace gridfree {
namespace {

using S = EtaJob::State;

TEST(StudyEta, NothingDoneUsesTheModelAsIs) {
  const Eta e = estimate_eta({{100, S::kQueued, 0, 0}, {50, S::kQueued, 0, 0}}, 2);
  EXPECT_DOUBLE_EQ(e.scale, 1.0);
  EXPECT_DOUBLE_EQ(e.seconds_left, 150.0);
  EXPECT_DOUBLE_EQ(e.eta_s, 75.0);
}

TEST(StudyEta, MeasuredTimesScaleTheModel) {
  // Done: model 10 + 30 = 40 s, measured 20 + 60 = 80 s → s = 2.
  // Left: queued 2·100 = 200; running 2·50 − 30 = 70; → 270 s, 135 s on 2 workers.
  const Eta e = estimate_eta(
      {{10, S::kDone, 20, 0}, {30, S::kDone, 60, 0}, {100, S::kQueued, 0, 0}, {50, S::kRunning, 0, 30}}, 2);
  EXPECT_DOUBLE_EQ(e.scale, 2.0);
  EXPECT_DOUBLE_EQ(e.seconds_left, 270.0);
  EXPECT_DOUBLE_EQ(e.eta_s, 135.0);
}

TEST(StudyEta, OverrunningJobCountsZeroNotNegative) {
  const Eta e = estimate_eta({{10, S::kRunning, 0, 50}}, 1);
  EXPECT_DOUBLE_EQ(e.seconds_left, 0.0);
}

TEST(StudyEta, HoursAndMinutes) {
  EXPECT_EQ(hours_minutes(30), "< 1 min");
  EXPECT_EQ(hours_minutes(7 * 60 + 10), "7 min");
  EXPECT_EQ(hours_minutes(2 * 3600 + 5 * 60), "2 h 05 min");
  EXPECT_EQ(hours_minutes(-1), "?");
}

// The case of the issue: instant workers, 368 jobs in 306 s at -j 2 (1.2
// jobs/s, the orchestrator's own cost), 9 350 left. The cost model prices
// the workers at nearly nothing ("< 1 min"); with the run's pace the ETA is
// about 9 350 × 0.83 s ≈ 2 h 09 min.
TEST(RunOverhead, PricesTheTimeTheWorkersDoNotExplain) {
  const RunPace pace{306.0, 368, 368 * 0.01};
  const double eta = with_run_overhead(5.0, pace, 9350, 2);
  const double g = (306.0 - 368 * 0.01 / 2) / 368;  // s per job beyond the workers
  EXPECT_NEAR(eta, 5.0 + g * 9350, 1e-9);
  EXPECT_GT(eta, 2 * 3600.0);
  EXPECT_EQ(hours_minutes(eta), "2 h 09 min");
}

TEST(RunOverhead, AddsNothingWhenTheWorkersFillTheTime) {
  // 10 jobs of 60 s on 2 workers in 300 s: the workers explain it all.
  EXPECT_DOUBLE_EQ(with_run_overhead(1200.0, {300.0, 10, 600.0}, 40, 2), 1200.0);
}

TEST(RunOverhead, WaitsForEnoughFinishedJobs) {
  EXPECT_DOUBLE_EQ(with_run_overhead(60.0, {100.0, kMinRunJobsForOverhead - 1, 0.0}, 1000, 2), 60.0);
  EXPECT_DOUBLE_EQ(with_run_overhead(60.0, {100.0, 50, 0.0}, 0, 2), 60.0);  // nothing left
}

}  // namespace
}  // namespace gridfree
