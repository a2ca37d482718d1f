// SPDX-License-Identifier: GPL-3.0-or-later
// The default per-job timeout, derived from the plan's cost model
// (study/study_plan.h) so that a hung or runaway worker is stopped without
// the user having to guess a limit:
//
//   timeout(N) = max(kMinJobTimeoutS, kJobTimeoutMargin · estimated_seconds(N, threads, r))
//
// with r the job's a-priori cost ratio (study/cost_model.h).
//
// The margin covers a machine several times slower or busier than the one
// the model was measured on and iteration counts well above the model's
// (docs/LIMITS.md); `--timeout S` overrides it, `--timeout none` disables it.
#pragma once

#include <array>

namespace gridfree {

inline constexpr double kJobTimeoutMargin = 20.0;
inline constexpr double kMinJobTimeoutS = 3600.0;

double default_job_timeout_s(const std::array<int, 3>& cells, int threads, double cost_ratio = 1);

}  // namespace gridfree
