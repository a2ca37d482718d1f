// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree plan --target-rde X` (docs/INTERFACE.md "plan"): which grids a
// target RDE needs and what they cost, before anything runs.
//
// Model of the finest grid's RDE as a function of its cell size:
//
//   RDE(Δ*) = a · Δ*^p
//
// fitted by least squares to log RDE = log a + p log Δ* over the stored
// (Δ*, RDE) of finished similar series (sched/target_prior.h), or, without
// them, a-priori: p = 1 and a = kAprioriRdeAtUnitDeltaStar (the bursting-
// bubble baseline: RDE 0.78 % at Δ* 0.564 with p = 1.00, docs/BENCHMARKS.md).
// The candidate grids are the study's ladder (adaptive grids) or its grid
// list, coarse to fine. Needed: the grids from the coarsest down to the first
// whose predicted RDE ≤ target, at least kMinGridsForConverged (a `converged`
// verdict needs n − 3 ≥ 2 degrees of freedom, docs/EXTRAPOLATION.md
// "Verdicts"; an adaptive series stops at its fifth grid at the earliest); a
// case with fewer candidate grids is not reachable whatever the predictions
// (enough_grids false, and the text says how many are missing). Cost:
// the plan's history rule where the database holds jobs similar to the
// grid's (study/cost_model.h), else the a-priori cost model's one-thread
// CPU time (study/study_plan.h with the case's a-priori ratio) times the
// measured scale s of the similar series (Σ cpu_s / Σ a-priori model; 1
// without them),
// peak memory the largest needed grid's estimate.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/cost_model.h"
#include "study/study.h"

namespace gridfree {

inline constexpr std::size_t kMinGridsForConverged = 5;
inline constexpr double kAprioriOrder = 1.0;
inline constexpr double kAprioriRdeAtUnitDeltaStar = 0.0078 / 0.564;

struct RdeModel {
  double p = kAprioriOrder;
  double a = kAprioriRdeAtUnitDeltaStar;    // RDE at Δ* = 1
  bool a_priori = true;
  std::size_t points = 0;                   // (Δ*, RDE) pairs fitted
  std::size_t similar_series = 0;
  double cost_scale = 1;                    // s above
  double predict(double delta_star) const;
};

// Least squares in logs; a-priori when fewer than two distinct Δ* with RDE > 0.
RdeModel fit_rde_model(const std::vector<std::array<double, 2>>& delta_star_rde);

struct TargetGrid {
  double delta_star = 0;
  std::array<int, 3> cells{};
  double predicted_rde = 0;
  double cpu_s = 0;                         // scaled cost-model estimate
  bool cost_from_history = false;           // cpu_s from finished similar jobs (else cost_scale × a-priori)
  double memory_bytes = 0;
  bool needed = false;
};

struct TargetCasePlan {
  std::string case_name;
  std::size_t series = 0;                   // series of the design on this case
  std::vector<TargetGrid> grids;            // coarse to fine
  std::size_t grids_needed = 0;
  bool reachable = false;                   // some candidate grid meets the target, and there are enough grids
  bool enough_grids = true;                 // at least kMinGridsForConverged candidate grids
  double cpu_s_per_series = 0;              // needed grids
  double peak_memory_bytes = 0;
  bool costs_from_history = false;          // some grid's cost ratio came from finished similar jobs
};

struct TargetPlan {
  double target_rde = 0;
  RdeModel model;
  std::vector<TargetCasePlan> cases;
  double total_cpu_s = 0;
  double peak_memory_bytes = 0;
};

// The candidate grids of a study for one case, coarse to fine: (Δ*, cells),
// the nominal Δ* where the study gives them, else the cells' actual Δ*.
std::vector<std::pair<double, std::array<int, 3>>> candidate_grids(const Study& study, const StudyCase& c);

// `history` (sched/cost_history.h): where it holds finished jobs similar to
// a grid's job (of the case's first series), that grid's cost is the plan's
// history rule (study/cost_model.h) instead of cost_scale × the a-priori model.
TargetPlan plan_for_target(const Study& study, double target_rde, const RdeModel& model,
                           const CostHistory& history = {});
std::string rde_model_text(const RdeModel& model);  // the RDE model and what it rests on
std::string cost_basis_text(const TargetPlan& plan); // where the grids' costs come from
nlohmann::json target_plan_json(const TargetPlan& plan);
std::string target_plan_text(const TargetPlan& plan);
// One line per case with fewer than kMinGridsForConverged grids (for the
// warnings of `plan`, on stderr and in --json).
std::vector<std::string> target_plan_warnings(const TargetPlan& plan);

}  // namespace gridfree
