// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates of external jobs (docs/EXTERNAL.md "Cost"): gridfree's own
// cost model (study/study_plan.h) describes its gas solver, not another
// code, so an external job's CPU time and memory come from
//   1. the case's declared per-cell figures (external.cost.cpu_s_per_cell,
//      mb_per_cell) × cells, else
//   2. its measured history: finished converged jobs of the same case
//      (cost_similarity_key: the same template, command, version), CPU
//      seconds fitted as a · cells^b (log-log least squares; b = 1 with one
//      measured size); peak memory (the worker's wait4 peak RSS of the
//      command) fitted as a + b · cells (least squares, a ≥ 0, b ≥ 0; with
//      one measured size: its peak, scaled by cells/cells₁ above that
//      size), never below a measured peak at as many cells or fewer, ×
//      kExternalMemorySafety, else
//   3. nothing: the estimate is unknown (NaN), shown as "unknown", never
//      invented.
// CPU and memory are decided separately (a declared cpu_s_per_cell with a
// measured memory history gives both).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "study/cost_model.h"
#include "study/study_plan.h"

namespace gridfree {

// The measured peak memory is scaled by this before it is used (the
// budget's need, plan, Slurm's --mem before its margin): peak RSS varies
// from run to run with the solver's allocations and the fit extrapolates.
inline constexpr double kExternalMemorySafety = 1.5;

struct ExternalJobCost {
  double cpu_s = NAN;         // NaN: unknown
  double memory_bytes = NAN;  // NaN: unknown
  std::string basis;          // "declared 0.002 s/cell", "history: 3 jobs, cpu ∝ cells^1.1", "unknown"
  std::string memory_basis;   // "declared 0.001 MB per cell", "history: ...", "unknown (...)"
};

// CPU seconds a · cells^b fitted to the samples (NaN without usable ones).
double fit_cpu_seconds(const std::vector<CostSample>& samples, double cells, double* exponent = nullptr);

// Peak memory in MiB from the samples' peak_rss_mb (rule 2 above, without
// the safety factor; NaN without usable samples).
double fit_memory_mb(const std::vector<CostSample>& samples, double cells);

// The rule above from the declared figures (either may be absent) and the
// case's measured samples (nullptr: none).
ExternalJobCost external_job_estimate(std::optional<double> cpu_s_per_cell, std::optional<double> mb_per_cell,
                                      const std::vector<CostSample>* samples, double cells);

ExternalJobCost external_job_cost(const ExternalCase& c, const nlohmann::json& job_doc, double cells,
                                  const CostHistory& history);

// The plan of an external study: one row per series, a case's jobs counted
// in its first series only (its other quantities read the same jobs).
Plan make_external_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                        const CostHistory& history);

}  // namespace gridfree
