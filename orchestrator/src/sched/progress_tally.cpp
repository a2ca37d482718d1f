// SPDX-License-Identifier: GPL-3.0-or-later
// ProgressTally (sched/progress_tally.h).
#include "sched/progress_tally.h"

#include <algorithm>
#include <utility>

#include "sched/study_eta.h"

namespace gridfree {

ProgressTally::ProgressTally(Sources sources, double recount_s, double eta_s)
    : sources_(std::move(sources)), recount_s_(recount_s), eta_s_(eta_s) {}

void ProgressTally::recount(double now) {
  const std::optional<double> eta = counts_.eta_s;
  counts_ = sources_.count();
  counts_.eta_s = eta;
  counted_at_ = now;
  count_cost_s_ = std::max(0.0, sources_.now_s() - now);
}

void ProgressTally::reprice(double now) {
  counts_.eta_s = sources_.eta ? sources_.eta() : std::nullopt;
  priced_at_ = now;
  eta_cost_s_ = std::max(0.0, sources_.now_s() - now);
}

ProgressCounts ProgressTally::with_pace(double now) const {
  ProgressCounts c = counts_;
  if (!first_start_ || finished_here_ < kMinRunJobsForOverhead) return c;
  const int left = std::max(0, c.total - c.done - c.failed);
  const double base = c.eta_s ? *c.eta_s : c.mean_wall_s * left / std::max(1, c.workers);
  c.eta_s = with_run_overhead(base, {now - *first_start_, finished_here_, worker_s_here_}, left, c.workers);
  return c;
}

ProgressCounts ProgressTally::current() {
  const double now = sources_.now_s();
  if (!counted_at_ || now - *counted_at_ >= std::max(recount_s_, kCostFactor * count_cost_s_)) recount(now);
  if (!priced_at_ || now - *priced_at_ >= std::max(eta_s_, kCostFactor * eta_cost_s_)) reprice(now);
  return with_pace(now);
}

ProgressCounts ProgressTally::exact() {
  const double now = sources_.now_s();
  recount(now);
  reprice(now);
  return with_pace(now);
}

void ProgressTally::job_started() {
  if (!first_start_) first_start_ = sources_.now_s();
  ++counts_.running;
}

void ProgressTally::job_finished(bool converged, double wall_s) {
  counts_.running = std::max(0, counts_.running - 1);
  ++(converged ? counts_.done : counts_.failed);
  ++finished_here_;
  worker_s_here_ += std::max(0.0, wall_s);
}

void ProgressTally::job_requeued() { counts_.running = std::max(0, counts_.running - 1); }

}  // namespace gridfree
