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
// large the study.
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
  void job_finished(bool converged);  // a final outcome was recorded
  void job_requeued();                    // queued again (retry, release)

 private:
  void recount(double now);
  void reprice(double now);

  Sources sources_;
  double recount_s_, eta_s_;
  ProgressCounts counts_;
  std::optional<double> counted_at_, priced_at_;
  double count_cost_s_ = 0, eta_cost_s_ = 0;  // duration of the last count and price
};

}  // namespace gridfree
