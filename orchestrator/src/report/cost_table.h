// SPDX-License-Identifier: GPL-3.0-or-later
// "What does a target cost": for every series and target RDE, the cheapest
// converged grid whose RDE (docs/PHYSICS.md §8, a-priori from the series'
// extrapolation) meets the target together with the RDE of every finer
// converged grid of the series, with its CPU time and the machine-independent
// cost cells × iterations. The finer grids must meet it too because on
// oscillatory convergence the RDE is not monotone in Δ*: a coarse grid that
// lands near f0 by chance has a small RDE that a refinement would not keep.
// Cheapest = least CPU time; a target no grid meets says "none of the run
// grids" (a finer grid is needed). Columns: series, verdict, target RDE,
// cheapest Δ*, cells, cells × iterations, CPU s, peak MB, its RDE.
#pragma once

#include <vector>

#include "report/series_summary.h"
#include "report/table.h"

namespace gridfree {

inline constexpr const char* kNoGridMeetsTarget = "none of the run grids";
inline const std::vector<double> kTargetRdes{0.10, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001};

// The grid of a series that meets `target` (with every finer grid) at the
// least CPU time, or null.
const GridPoint* cheapest_grid_for(const SeriesSummary& s, double target);

Table cost_table(const std::vector<SeriesSummary>& series, const std::vector<double>& targets = kTargetRdes);

}  // namespace gridfree
