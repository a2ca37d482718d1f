// SPDX-License-Identifier: GPL-3.0-or-later
// Progress counts at a cost per event that does not grow with the study.
//
// Counting a study in the store reads every one of its jobs, and its ETA
// prices every remaining job (sched/study_eta.h): done after every job start
// and finish, that made `run` quadratic in the number of jobs. The tally
// counts the store at most every `recount_s` seconds and prices the ETA at
// most every `eta_s` seconds; in between, this process's own events move
// the counts (a start: running + 1; a converged result: running − 1,
// done + 1; any other final outcome: running − 1, failed + 1; a requeue:
// running − 1), as the store counts jobs `done` and `failed`; other
// processes' work shows at the next recount. `exact()` recounts now (the
// last line of a run). A count or price that takes long (both read the
// whole study) waits kCostFactor times its own duration before the next,
// so each takes at most about 1/kCostFactor of the loop's time however
// large the study. The ETA returned includes this run's own pace
// (sched/study_eta.h with_run_overhead: the wall time per job the workers'
// times do not explain × the jobs left); without a priced ETA the base is
// the mean wall time × jobs left / workers.
#pragma once

#include <functional>
#include <optional>

#include "sched/progress.h"

namespace gridfree {

class ProgressTally {
 public:
  struct Sources {
    std::function<ProgressCounts()> count;          // counts from the store, without eta_s
    std::function<std::optional<double>()> eta;     // the ETA in seconds, when it can be priced
    std::function<double()> now_s;                  // a monotonic clock in seconds
  };
  static constexpr double kCostFactor = 20;
  ProgressTally(Sources sources, double recount_s = 1.0, double eta_s = 10.0);

  ProgressCounts current();  // recounted (and re-priced) when stale
  ProgressCounts exact();    // recounted and re-priced now

  void job_started();
  // A final outcome was recorded; `wall_s`: the worker's wall time.
  void job_finished(bool converged, double wall_s = 0);
  void job_requeued();                    // queued again (retry, release)

 private:
  void recount(double now);
  void reprice(double now);
  ProgressCounts with_pace(double now) const;

  Sources sources_;
  double recount_s_, eta_s_;
  ProgressCounts counts_;
  std::optional<double> counted_at_, priced_at_;
  double count_cost_s_ = 0, eta_cost_s_ = 0;  // duration of the last count and price
  std::optional<double> first_start_;          // this run's first job start
  int finished_here_ = 0;                      // final outcomes recorded by this run
  double worker_s_here_ = 0;                   // their workers' wall time
};

}  // namespace gridfree
