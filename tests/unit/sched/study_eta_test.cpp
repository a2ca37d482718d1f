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

}  // namespace
}  // namespace gridfree
