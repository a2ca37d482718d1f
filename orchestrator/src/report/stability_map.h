// SPDX-License-Identifier: GPL-3.0-or-later
// "Where methods fail" (docs/REPORTS.md, stability map): the outcome of
// every grid of every series, one row per series and one column per Δ*, a
// line per series saying down to which Δ* it converges and where and why it
// first fails, and how often the classic three-grid GCI gave a usable answer
// beside the least-squares extrapolation.
//
// Outcome words (also the column `outcome` of the view v_stability,
// store/stability_view.h, which classifies the same way):
//   converged      the steady criterion was met (with its outer iterations)
//   stalled        not_converged by numerics.stall_window: a limit cycle
//   iteration_cap  not_converged at numerics.max_iterations
//   diverged       the residuals blew up (no dp*)
//   invalid        the job has no solution (ε_s ≥ 1 in a cell) or was refused
//   timed_out      stopped at the study's timeout_s, attempts spent
//   failed         anything else (a crash, a lost result)
//   pending        queued or running;  cancelled  cancelled before it ran
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "report/report_data.h"
#include "report/series_summary.h"
#include "study/case_vocabulary.h"

namespace gridfree {

// The outcome word of a grid from its status (result status, else job
// status), its reason and the worker's result `outcome` field (empty for
// results written before it existed: then the reason decides stalled).
std::string grid_outcome(const std::string& status, const std::string& reason, const std::string& worker_outcome);
std::string grid_outcome(const GridPoint& grid);

// True for the outcomes of a finished grid without a usable value.
bool is_failure_outcome(const std::string& outcome);

struct StabilityCell {
  bool present = false;          // the series has a grid in this column
  std::string outcome;
  int iterations = 0;
  double delta_star = 0;         // the grid's actual Δ*
  std::string reason;
  int remedy_from = 0;           // numerics.stall_remedy acted from this outer iteration (0: it did not)
};

// How the two extrapolations fared on one series (docs/REPORTS.md).
struct MethodTally {
  int triplets = 0;              // consecutive triplets of converged grids
  int gci_usable = 0;            // of which the GCI is usable: monotone, p in the study's range
  int divergent = 0, oscillatory = 0, p_out_of_range = 0, no_number = 0;
  bool least_squares_usable = false;  // the regression gave f0 (with U)
  std::string least_squares;     // "f0 by capped_power" or why not
};

struct StabilityRow {
  std::string label;
  std::vector<StabilityCell> cells;   // one per column of the map
  int failures = 0, converged = 0, pending = 0;
  std::string line;                   // "converges down to Δ* X; first failure at Δ* Y: reason"
  MethodTally methods;
};

struct StabilityMap {
  std::vector<double> columns;        // Δ* of each column (3 significant digits), coarsest first
  std::vector<StabilityRow> rows;     // failures first, at most the row cap
  int omitted = 0;                    // rows left out by the cap (all of them converged on every grid, if
                                      // the cap is not smaller than the number of series with a failure)
  int series_total = 0, series_with_failures = 0;
  CaseVocabulary words = case_vocabulary(CaseKindId::particle_bed);  // the study's: h or Δ*, iterations counted?
};

inline constexpr std::size_t kStabilityMapMaxRows = 60;

// The series' line: "converges down to Δ* X; first failure at Δ* Y: reason"
// (walking from the coarsest grid), or what holds instead.
std::string stability_line(const SeriesSummary& series);

// Whether the GCI of one triplet is usable (docs/REPORTS.md): "usable" when
// its convergence is monotone, it has p and φ_ext, and p lies in
// [p_low, p_high]; else the reason: "divergent", "oscillatory", "no p",
// "p outside [p_low, p_high]". The GCI table and the tally below both use it.
std::string gci_usability(const GciView& triplet, double p_low, double p_high);

// The GCI and least-squares tally of a series; p_low, p_high: the study's
// accepted range of the order.
MethodTally method_tally(const SeriesSummary& series, double p_low, double p_high);

// The map: rows sorted with the series that have failures first (most
// failures first, then study order), cut at max_rows.
StabilityMap stability_map(const std::vector<SeriesSummary>& series, double p_low, double p_high,
                           std::size_t max_rows = kStabilityMapMaxRows);

}  // namespace gridfree
