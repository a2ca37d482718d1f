// SPDX-License-Identifier: GPL-3.0-or-later
// ProgressTally: the store is counted at most once per recount interval and
// the ETA priced at most once per ETA interval; the scheduler's own events
// move the counts in between, and exact() recounts at once.
#include <gtest/gtest.h>

#include "sched/progress_tally.h"

namespace gridfree {
namespace {

struct TallyProbe {
  double clock = 0;
  int counted = 0, priced = 0;
  ProgressCounts stored;  // what the store would say
  ProgressTally tally() {
    ProgressTally::Sources s;
    s.count = [this] {
      ++counted;
      return stored;
    };
    s.eta = [this]() -> std::optional<double> {
      ++priced;
      return 60.0 * priced;
    };
    s.now_s = [this] { return clock; };
    return ProgressTally(std::move(s), 1.0, 10.0);
  }
};

TEST(ProgressTally, CountsTheStoreOncePerIntervalAndAppliesOwnEventsInBetween) {
  TallyProbe probe;
  probe.stored.total = 100;
  probe.stored.running = 1;
  auto tally = probe.tally();
  tally.job_started();
  auto c = tally.current();
  EXPECT_EQ(probe.counted, 1);
  EXPECT_EQ(c.running, 1);  // the store's count replaces the local one
  for (int i = 0; i < 50; ++i) {  // 50 jobs finish within the same second
    tally.job_finished(i % 10 != 0);
    tally.job_started();
    c = tally.current();
  }
  EXPECT_EQ(probe.counted, 1);
  EXPECT_EQ(probe.priced, 1);
  EXPECT_EQ(c.done, 45);
  EXPECT_EQ(c.failed, 5);
  EXPECT_EQ(c.running, 1);
  EXPECT_EQ(c.total, 100);
  ASSERT_TRUE(c.eta_s);
  EXPECT_EQ(*c.eta_s, 60.0);
}

TEST(ProgressTally, RecountsAfterTheIntervalAndPricesTheEtaLessOften) {
  TallyProbe probe;
  probe.stored.total = 10;
  auto tally = probe.tally();
  tally.current();
  probe.stored.done = 7;  // another process finished jobs
  probe.clock = 0.5;
  EXPECT_EQ(tally.current().done, 0);
  probe.clock = 1.0;
  auto c = tally.current();
  EXPECT_EQ(c.done, 7);
  EXPECT_EQ(probe.counted, 2);
  EXPECT_EQ(probe.priced, 1);
  EXPECT_EQ(*c.eta_s, 60.0);  // the ETA is kept across a recount
  probe.clock = 10.0;
  EXPECT_EQ(*tally.current().eta_s, 120.0);
  EXPECT_EQ(probe.priced, 2);
}

TEST(ProgressTally, ExactRecountsAndRepricesNow) {
  TallyProbe probe;
  auto tally = probe.tally();
  tally.current();
  probe.stored.failed = 3;
  const auto c = tally.exact();
  EXPECT_EQ(c.failed, 3);
  EXPECT_EQ(probe.counted, 2);
  EXPECT_EQ(probe.priced, 2);
}

TEST(ProgressTally, RequeuesOnlyFreeTheRunningSlot) {
  TallyProbe probe;
  probe.stored.running = 2;
  auto tally = probe.tally();
  tally.current();
  tally.job_requeued();
  tally.job_requeued();
  tally.job_requeued();  // never below zero
  const auto c = tally.current();
  EXPECT_EQ(c.running, 0);
  EXPECT_EQ(c.done + c.failed, 0);
}

TEST(ProgressTally, ACostlyCountWaitsTwentyTimesItsDuration) {
  TallyProbe probe;
  double count_s = 2.0;  // each count of the store takes 2 s (a very large study)
  ProgressTally::Sources s;
  s.count = [&] {
    ++probe.counted;
    probe.clock += count_s;
    return probe.stored;
  };
  s.now_s = [&] { return probe.clock; };
  ProgressTally tally(std::move(s), 1.0, 10.0);
  tally.current();  // counted from 0 to 2 s
  EXPECT_EQ(probe.counted, 1);
  probe.clock = 0 + 39.9;  // 20 × 2 s after the count started, minus a little
  tally.current();
  EXPECT_EQ(probe.counted, 1);
  probe.clock = 40.0;
  tally.current();
  EXPECT_EQ(probe.counted, 2);
  count_s = 0;  // cheap again: back to once a second
  probe.clock = 80.0;
  tally.current();
  probe.clock = 81.0;
  tally.current();
  EXPECT_EQ(probe.counted, 4);
}

TEST(ProgressTally, TheEtaIncludesThisRunsOwnPace) {
  TallyProbe probe;  // the priced ETA: 60 s (the cost model's, workers only)
  probe.stored.total = 1000;
  probe.stored.workers = 2;
  auto tally = probe.tally();
  tally.job_started();  // at t = 0
  for (int i = 0; i < 10; ++i) {
    probe.clock += 1.0;  // one job per second, each 0.1 s in its worker
    tally.job_finished(true, 0.1);
    if (i < 9) tally.job_started();
  }
  probe.stored.done = 10;
  const auto c = tally.exact();  // priced: 60 s
  ASSERT_TRUE(c.eta_s);
  // g = (10 s − 10 × 0.1 s / 2) / 10 = 0.95 s per job, 990 jobs left.
  EXPECT_NEAR(*c.eta_s, 60.0 + 0.95 * 990, 1e-9);
}

}  // namespace
}  // namespace gridfree
