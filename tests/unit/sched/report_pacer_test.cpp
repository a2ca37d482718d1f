// SPDX-License-Identifier: GPL-3.0-or-later
// ReportPacer: the first report at once, then at most one write per
// max(min interval, cost factor × the last write's duration); every pending
// study is listed when all are asked for.
#include <gtest/gtest.h>

#include "sched/report_pacer.h"

namespace gridfree {
namespace {

using Studies = std::vector<long long>;

TEST(ReportPacer, WritesTheFirstReportAtOnceThenPausesByItsCost) {
  ReportPacer pacer(2.0, 5.0);
  EXPECT_EQ(pacer.pending(0.0), Studies{});
  pacer.series_finished(7);
  EXPECT_EQ(pacer.pending(0.0), Studies{7});
  pacer.written(7, 0.0, 1.0);  // a write of 1 s: the next no sooner than 5 s later
  EXPECT_EQ(pacer.pending(), Studies{});
  pacer.series_finished(7);
  pacer.series_finished(7);
  EXPECT_EQ(pacer.pending(5.9), Studies{});
  EXPECT_EQ(pacer.pending(), Studies{7});  // idle or at the end: written anyway
  EXPECT_EQ(pacer.pending(6.0), Studies{7});
  pacer.written(7, 6.0, 6.1);  // a fast write: the minimum interval applies
  pacer.series_finished(7);
  EXPECT_EQ(pacer.pending(8.0), Studies{});
  EXPECT_EQ(pacer.pending(8.1), Studies{7});
}

TEST(ReportPacer, PacesEachStudyOnItsOwn) {
  ReportPacer pacer(2.0, 5.0);
  pacer.series_finished(1);
  pacer.written(1, 0.0, 10.0);
  pacer.series_finished(1);
  pacer.series_finished(2);
  EXPECT_EQ(pacer.pending(11.0), Studies{2});
  EXPECT_EQ(pacer.pending(60.0), (Studies{1, 2}));
}

}  // namespace
}  // namespace gridfree
