// SPDX-License-Identifier: GPL-3.0-or-later
// ReportPacer (sched/report_pacer.h).
#include "sched/report_pacer.h"

#include <algorithm>

namespace gridfree {

ReportPacer::ReportPacer(double min_interval_s, double cost_factor)
    : min_interval_s_(min_interval_s), cost_factor_(cost_factor) {}

void ReportPacer::series_finished(long long study) { studies_[study].pending = true; }

std::vector<long long> ReportPacer::pending(std::optional<double> now) const {
  std::vector<long long> out;
  for (const auto& [study, s] : studies_)
    if (s.pending && (!now || *now >= s.next_at)) out.push_back(study);
  return out;
}

void ReportPacer::written(long long study, double started, double ended) {
  State& s = studies_[study];
  s.pending = false;
  s.next_at = ended + std::max(min_interval_s_, cost_factor_ * (ended - started));
}

}  // namespace gridfree
