// SPDX-License-Identifier: GPL-3.0-or-later
// The plan of an external study (docs/EXTERNAL.md "Validate and plan"),
// from the cost estimates of study/external_cost.h.
#pragma once

#include <string>

#include "study/cost_model.h"
#include "study/external_cost.h"
#include "study/study_plan.h"

namespace gridfree {

ExternalJobCost external_job_cost(const ExternalCase& c, const nlohmann::json& job_doc, double cells,
                                  const CostHistory& history);

// The plan of an external study: one row per series, a case's jobs counted
// in its first series only (its other quantities read the same jobs). A
// row's memory is the largest of its grids' (unknown when one of them is),
// its CPU time their sum (unknown when one is), each with the sentence of
// the grid that decides it (the first unknown one, else the largest).
Plan make_external_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                        const CostHistory& history);

}  // namespace gridfree
