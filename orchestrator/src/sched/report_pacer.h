// SPDX-License-Identifier: GPL-3.0-or-later
// When the scheduler rewrites a study's report while its series finish.
//
// A report is rebuilt whole (report/report.h), at a cost that grows with the
// study; rewritten after every finished series, it made `run` quadratic in
// the number of series. The pacer writes a study's first report at once and
// then at most once per max(min_interval_s, cost_factor × the duration of
// its last write): the report is never more than that behind, and writing
// takes at most 1/cost_factor of the time. A series that finishes in a
// pause leaves the study pending; the scheduler writes pending reports when
// their pause is over, when it is idle, and when it ends (`run` writes its
// final report itself).
#pragma once

#include <map>
#include <optional>
#include <vector>

namespace gridfree {

class ReportPacer {
 public:
  explicit ReportPacer(double min_interval_s = 2.0, double cost_factor = 5.0);

  void series_finished(long long study);
  // Studies with finished series not yet in their report; `now` given: only
  // those whose pause is over.
  std::vector<long long> pending(std::optional<double> now = std::nullopt) const;
  // A write of the study's report ran from `started` to `ended` (seconds).
  void written(long long study, double started, double ended);

 private:
  struct State {
    bool pending = false;
    double next_at = 0;  // earliest time of the next write
  };
  double min_interval_s_, cost_factor_;
  std::map<long long, State> studies_;
};

}  // namespace gridfree
