// SPDX-License-Identifier: GPL-3.0-or-later
// The rungs of an external case's adaptive ladder when a series is decided
// (sched/adaptive_series.h, docs/EXTERNAL.md "Adaptive series"): the ladder
// of study/external_ladder.h from the stored study definition, each rung's
// job document (the series' first job with the rung's variables and grid),
// and its cost by the external estimate (study/external_plan.h): the
// declared cost.cpu_s_per_cell × cells, else a · cells^b fitted to
// `measured` (the series' own finished jobs); NaN (unknown) otherwise.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/cost_model.h"
#include "study/adaptive_rungs.h"

namespace gridfree {

struct ExternalRungs {
  std::vector<AdaptiveRung> rungs;      // delta_star: the nominal h; cells {cells, 1, 1}; label "N = 57"
  std::vector<nlohmann::json> specs;    // the job document of each rung
  std::vector<double> h;                // each rung's actual h
};

ExternalRungs external_rungs(const nlohmann::json& definition, const AdaptiveGrids& settings,
                             const std::string& case_name, const nlohmann::json& first_spec,
                             const CostHistory& measured);

}  // namespace gridfree
