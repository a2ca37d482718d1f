// SPDX-License-Identifier: GPL-3.0-or-later
// The case-dependent factor of the cost model (docs/ORCHESTRATOR.md "Cost
// model"). The base model (study/study_plan.h) was fitted to the bursting
// bubble; a job's estimate is
//
//   time(job) = r · I(N) · N · c / threads
//
// with I(N) and c from study_plan.h and r the job's cost ratio, chosen by
// this rule:
//
// (a) history: the database holds finished, converged jobs *similar* to
//     this one (same case object without `name` and `particles` — domain,
//     particle diameter, gas, gravity, boundaries, probes — and the same
//     drag law). Each gives r_j = cpu_s_j / (I(N_j) · N_j · c); r is the
//     median of r_j over the similar jobs nearest in cell count: those
//     within a factor kHistoryCellWindow of N, else those at the nearest
//     measured N (the ratio is taken as constant beyond the measured range).
// (b) a-priori, without history: r from the particle Reynolds number
//     Re_p = ρ_g U0 d / μ_g. An inertial bed needs more outer iterations
//     than the bubble (Re_p = 1) and the nested start (N ≥ kNestedMinCells)
//     saves fewer of them; side walls were measured not to matter:
//
//       r = 1 + (r_ref(N) − 1) · clamp(ln Re_p / ln kReferenceReP, 0, 1)
//
//     r_ref = the median measured ratio of the SSCP-like bed (Re_p 475) on
//     single grids and on nested-start grids; log-linear in between (the
//     SSCP-like bed's ratios measured at Re_p 20, 100 and 475 lie within
//     1.3× of it; at Re_p 1 that bed is cheaper than the bubble, 0.35–1.2,
//     which r = 1 over-estimates), constant above (not measured).
//
// Pure functions; the database is read by sched/cost_history.h.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

// A-priori ratios (docs/ORCHESTRATOR.md "Cost model", measured 2026-11-29):
// the medians over the 83 converged jobs of the SSCP-like six-instance study
// (35 below 20 000 cells, 48 above: the nested-start threshold of solver/4).
inline constexpr double kReferenceReP = 475.0;
inline constexpr double kReferenceSingleGridRatio = 1.45;
inline constexpr double kReferenceNestedRatio = 2.6;
inline constexpr double kHistoryCellWindow = 2.0;      // similar jobs within N/2 … 2N

enum class CostSource { kAPriori, kHistory };
std::string cost_source_name(CostSource s);  // "a-priori" | "history"

struct CostRatio {
  double ratio = 1;
  CostSource source = CostSource::kAPriori;
  std::size_t jobs = 0;      // history: the similar jobs the median was taken over
  std::string basis;         // one sentence: where the ratio comes from
};

// Re_p = ρ_g U0 d / μ_g of a case object, U0 the superficial velocity of
// its y_low mass inflow (0 without one).
double particle_reynolds(const nlohmann::json& case_doc);

// (b) above, from a job document (its "case" object) and its grid.
CostRatio apriori_cost_ratio(const nlohmann::json& job_doc, const std::array<int, 3>& cells);

// What makes two jobs similar for (a): the case without name and particles,
// and the drag law (canonical JSON text).
std::string cost_similarity_key(const nlohmann::json& job_doc);

// One finished job: its cell count, measured CPU seconds and peak memory
// (MiB, the worker's peak RSS; 0 when not recorded).
struct CostSample {
  double cells = 0;
  double cpu_s = 0;
  double peak_rss_mb = 0;
};
using CostHistory = std::map<std::string, std::vector<CostSample>>;  // by similarity key

// (a) above for a job of `cells` cells from its similar jobs; ratio 0 and
// jobs 0 when there are none.
CostRatio history_cost_ratio(const std::vector<CostSample>& similar, double cells);

// The rule: (a) when the history holds similar jobs, else (b).
CostRatio job_cost_ratio(const CostHistory& history, const nlohmann::json& job_doc,
                         const std::array<int, 3>& cells);

}  // namespace gridfree
