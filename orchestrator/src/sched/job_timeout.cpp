// SPDX-License-Identifier: GPL-3.0-or-later
// The default per-job timeout (sched/job_timeout.h).
#include "sched/job_timeout.h"

#include <algorithm>

#include "study/study_plan.h"

namespace gridfree {

double default_job_timeout_s(const std::array<int, 3>& cells, int threads, double cost_ratio) {
  return std::max(kMinJobTimeoutS, kJobTimeoutMargin * estimated_seconds(cells, threads, cost_ratio));
}

}  // namespace gridfree
