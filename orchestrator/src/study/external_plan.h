// Cost estimates of external jobs (docs/EXTERNAL.md "Cost"): gridfree's own
// cost model (study/study_plan.h) describes its gas solver, not another
// code, so an external job's CPU time and memory come from
//   1. the case's declared per-cell figures (external.cost.cpu_s_per_cell,
//      mb_per_cell) × cells, else
//   2. its measured history: finished converged jobs of the same case
//      (cost_similarity_key: the same template, command, version), CPU
//      seconds fitted as a · cells^b (log-log least squares; b = 1 with one
//      measured size), else
//   3. nothing: the estimate is unknown (NaN), shown as "unknown", never
//      invented.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "study/cost_model.h"
#include "study/study_plan.h"

namespace gridfree {

struct ExternalJobCost {
  double cpu_s = NAN;         // NaN: unknown
  double memory_bytes = NAN;  // NaN: unknown
  std::string basis;          // "declared 0.002 s/cell", "history: 3 jobs, cpu ∝ cells^1.1", "unknown"
};

// CPU seconds a · cells^b fitted to the samples (NaN without usable ones).
double fit_cpu_seconds(const std::vector<CostSample>& samples, double cells, double* exponent = nullptr);

ExternalJobCost external_job_cost(const ExternalCase& c, const nlohmann::json& job_doc, double cells,
                                  const CostHistory& history);

// The plan of an external study: one row per series, a case's jobs counted
// in its first series only (its other quantities read the same jobs).
Plan make_external_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                        const CostHistory& history);

}  // namespace gridfree
