// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive grid series (docs/INTERFACE.md §3, docs/EXTRAPOLATION.md
// "Adaptive series"): a study's grids given as a target instead of a list,
//
//   "grids": {"target_rde": 0.01, "coarsest_delta_star": 3.3, "ratio": 1.2,
//             "finest_delta_star": 0.16, "max_cpu_s": 3600, "max_memory": "8 GiB"}
//
// The ladder of candidate grids is geometric, coarse to fine:
//
//   Δ*_k = coarsest_delta_star / ratio^k,  k = 0 .. K,
//   K = the largest k with Δ*_k ≥ finest_delta_star (to a relative 1e-9).
//
// A series starts with the first kFirstGrids rungs; the orchestrator adds
// one rung at a time after that (sched/adaptive_series.h).
//
// External studies (study/external_ladder.h) give the ladder by their one
// grid variable instead of Δ*:
//
//   "grids": {"target_rde": 0.02, "ratio": 1.41,
//             "variables": {"N": {"coarsest": 20, "finest": 160}}}
//
// and the ladder is in each case's h: h_k = h(coarsest) / ratio^k down to
// h(finest), each rung's variable found by inverting h.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// The grid variable an external study's ladder refines.
struct AdaptiveVariable {
  std::string name;
  double coarsest = 0, finest = 0;  // the variable's values at the two ends of the ladder
  bool integer = true;              // "type": integer (rounded to the nearest integer) or real
};

struct AdaptiveGrids {
  double target_rde = 0.01;                 // RDE of the finest grid to reach (fraction)
  double coarsest_delta_star = 0;
  double ratio = 0;                         // Δ*_k / Δ*_{k+1} ≥ 1.1 (study/grid_listing.h)
  double finest_delta_star = 0;
  std::optional<double> max_cpu_s;          // cap: predicted CPU seconds of the next job
  std::optional<double> max_memory_bytes;   // cap: estimated memory of the next job (default: the machine's)
  std::optional<AdaptiveVariable> variable; // external studies: the ladder is in h (Δ* fields unused)

  // Grids run before the first extrapolation: the least-squares fits need 4
  // (docs/PHYSICS.md §8).
  static constexpr std::size_t kFirstGrids = 4;
  // Fewest rungs a ladder may have: a `converged` verdict needs n − 3 ≥ 2
  // degrees of freedom (docs/EXTRAPOLATION.md "Verdicts").
  static constexpr std::size_t kMinLadder = 5;
};

// The ladder Δ*_0 > Δ*_1 > ... > Δ*_K (see above); empty for an external
// study's ladder (study/external_ladder.h).
std::vector<double> adaptive_ladder(const AdaptiveGrids& a);

// Reads and checks the adaptive form of "grids" (the object at /grids); every
// problem is added with its pointer. Returns nullopt when there are problems.
std::optional<AdaptiveGrids> parse_adaptive_grids(const nlohmann::json& grids, ProblemList& problems);

// The adaptive settings of a stored (already validated) study definition,
// or nullopt for a study with a grid list.
std::optional<AdaptiveGrids> adaptive_grids_of(const nlohmann::json& definition);

// "12 GiB", "500 MiB", "2.5 GB", or a number of bytes → bytes; nullopt if
// not understood.
std::optional<double> parse_memory_field(const nlohmann::json& value);

}  // namespace gridfree
