// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates of external jobs (docs/EXTERNAL.md "Cost, timeouts,
// memory"): gridfree's own cost model (study/study_plan.h) describes its
// gas solver, not another code, so an external job's CPU time and memory
// are never invented. Each is decided on its own, from
//   1. the case's declared per-cell figure (external.cost.cpu_s_per_cell,
//      mb_per_cell) × cells, plus the fixed part the case's measured jobs
//      show beyond it (max over them of measured − figure × cells, ≥ 0; for
//      memory × kExternalMemorySafety), else
//   2. the measured history of the case (finished converged jobs of the
//      same template, command and version: cost_similarity_key):
//      - at two or more distinct sizes: CPU seconds a · cells^b (log-log
//        least squares), peak memory a + b · cells (least squares, a, b ≥ 0:
//        a is the fixed footprint, never multiplied by cells), neither below
//        a value measured at as many cells or fewer; memory × the safety;
//      - at one size: that size's figure for jobs of as many cells or fewer
//        (CPU and memory do not fall with cells); unknown above it, since one
//        size cannot tell a fixed footprint from what grows with cells (a
//        107 MiB run at 64 cells scaled with cells would claim 160 GiB at
//        65 536), so the next larger grid runs alone and gives the second
//        size;
//   3. otherwise unknown (NaN), shown as such.
// Every estimate carries the sentence saying which rule gave it.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/cost_model.h"

namespace gridfree {

// The measured peak memory is scaled by this before it is used (the
// budget's need, plan, Slurm's --mem before its margin): peak RSS varies
// from run to run with the solver's allocations and the fit extrapolates.
inline constexpr double kExternalMemorySafety = 1.5;

struct ExternalJobCost {
  double cpu_s = NAN;         // NaN: unknown
  double memory_bytes = NAN;  // NaN: unknown
  std::string basis;          // where cpu_s comes from: "declared ...", "history: ...", "unknown ..."
  std::string memory_basis;   // where memory_bytes comes from
};

// A fit of one measured figure against cells (rule 2), with its sentence.
struct CostFit {
  double value = NAN;  // at the asked cells; NaN: unknown
  double exponent = NAN;  // CPU: b of a · cells^b (two sizes or more)
  double fixed = NAN, per_cell = NAN;  // memory: a and b of a + b · cells (two sizes or more)
  std::size_t samples = 0, sizes = 0;  // usable measurements and their distinct cell counts
  std::string basis;
};

// CPU seconds of a job of `cells` cells from the samples' cpu_s (rule 2).
CostFit fit_cpu_seconds(const std::vector<CostSample>& samples, double cells);
// Peak memory in MiB from the samples' peak_rss_mb (rule 2, without the
// safety factor).
CostFit fit_memory_mb(const std::vector<CostSample>& samples, double cells);

// The rule above from the declared figures (either may be absent) and the
// case's measured samples (nullptr: none).
ExternalJobCost external_job_estimate(std::optional<double> cpu_s_per_cell, std::optional<double> mb_per_cell,
                                      const std::vector<CostSample>* samples, double cells);

// An external case's declared cost figures (external.cost).
struct DeclaredCost {
  std::optional<double> cpu_s_per_cell, mb_per_cell;
};
// Case name → its declared cost (only external cases; none declared: empty fields).
std::map<std::string, DeclaredCost> declared_external_costs(const nlohmann::json& definition);

}  // namespace gridfree
