// SPDX-License-Identifier: GPL-3.0-or-later
// The rungs of an adaptive ladder for one case (study/adaptive_grids.h) with
// their cells (round(L*/Δ*) per direction, grid/grid.h) and the cost model's
// estimates (study/study_plan.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "study/adaptive_grids.h"

namespace gridfree {

struct AdaptiveRung {
  double delta_star = 0;          // nominal Δ* of the ladder
  std::array<int, 3> cells{};
  double model_cpu_s = 0;         // cost model, one thread (core-seconds)
  double memory_bytes = 0;        // estimated peak memory
  std::string label;              // an external rung: its variable and cells ("N = 57, 3249 cells"); "" otherwise
};

std::vector<AdaptiveRung> adaptive_rungs(const std::vector<double>& ladder, const std::array<double, 3>& domain_dp);

}  // namespace gridfree
