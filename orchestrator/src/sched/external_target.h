// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree plan --target-rde X` of an external study (docs/EXTERNAL.md
// "Adaptive series and plan --target-rde"): for each series (case ×
// quantity), which of the study's grids (its grid list, or its adaptive
// ladder's rungs) reach the target and what they cost.
//
// RDE model, per series: RDE(h) = a · h^p fitted by least squares in logs
// (study/target_plan.h fit_rde_model) to the stored (h, RDE) of every grid
// of the finished series in the database of the same case (the same
// template, command and version: study/cost_model.h cost_similarity_key)
// and quantity. gridfree's a-priori RDE model describes its own solver, so
// without such a series the prediction is unknown (said so, never
// invented). Needed: the grids from the coarsest down to the first whose
// predicted RDE ≤ target, at least kMinGridsForConverged. Cost: the
// external estimate (study/external_plan.h: declared, history fit, or
// unknown). The database is only read.
#pragma once

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/cost_model.h"
#include "study/study.h"
#include "study/target_plan.h"

namespace gridfree {

struct ExternalTargetGrid {
  double h = 0;
  std::map<std::string, double> variables;  // the grid variables
  double cells = NAN;                       // NaN without a cells expression
  double predicted_rde = NAN;               // NaN: no model
  double cpu_s = NAN;                       // NaN: unknown
  std::string cost_basis;
  bool needed = false;
};

struct ExternalTargetSeries {
  std::string label;                        // "cavity mean_u2"
  RdeModel model;                           // a_priori = true: none fitted (unknown)
  std::vector<ExternalTargetGrid> grids;    // coarse to fine
  std::size_t grids_needed = 0;
  bool reachable = false;
  double cpu_s = 0;                         // the needed grids (NaN when one is unknown)
};

struct ExternalTargetPlan {
  double target_rde = 0;
  std::vector<ExternalTargetSeries> series;
};

ExternalTargetPlan plan_external_target(const Study& study, const ExpandedStudy& expanded, double target_rde,
                                        const std::filesystem::path& db_file, const CostHistory& history);
std::string external_target_text(const ExternalTargetPlan& plan);
nlohmann::json external_target_json(const ExternalTargetPlan& plan);

}  // namespace gridfree
