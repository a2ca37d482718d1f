// SPDX-License-Identifier: GPL-3.0-or-later
// ETA of a study from the cost model and measured times (see study_eta.h).
#include "sched/study_eta.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridfree {

Eta estimate_eta(const std::vector<EtaJob>& jobs, int workers) {
  double measured = 0, modelled = 0;
  for (const auto& j : jobs)
    if (j.state == EtaJob::State::kDone && j.model_s > 0 && j.wall_s > 0) {
      measured += j.wall_s;
      modelled += j.model_s;
    }
  Eta e;
  if (modelled > 0) e.scale = measured / modelled;
  for (const auto& j : jobs) {
    if (j.state == EtaJob::State::kQueued) e.seconds_left += e.scale * j.model_s;
    if (j.state == EtaJob::State::kRunning) e.seconds_left += std::max(0.0, e.scale * j.model_s - j.elapsed_s);
  }
  e.eta_s = e.seconds_left / std::max(1, workers);
  return e;
}

double with_run_overhead(double eta_s, const RunPace& pace, int jobs_left, int workers) {
  if (pace.finished < kMinRunJobsForOverhead || jobs_left <= 0) return eta_s;
  const double unexplained = std::max(0.0, pace.elapsed_s - pace.worker_s / std::max(1, workers));
  return eta_s + unexplained / pace.finished * jobs_left;
}

std::string hours_minutes(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  if (seconds < 60) return "< 1 min";
  const long long minutes = std::llround(seconds / 60);
  char buf[48];
  if (minutes < 60)
    std::snprintf(buf, sizeof buf, "%lld min", minutes);
  else
    std::snprintf(buf, sizeof buf, "%lld h %02lld min", minutes / 60, minutes % 60);
  return buf;
}

}  // namespace gridfree
