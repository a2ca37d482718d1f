// SPDX-License-Identifier: GPL-3.0-or-later
// One verdict per series, a pure function of the extrapolation's numbers
// (docs/EXTRAPOLATION.md "Verdicts", docs/PHYSICS.md §8). With n converged
// grids, f0 the extrapolated value, R_f = (max f − min f)/(n − 1), σ_RE/R_f the
// fit quality, RDE_1 the relative uncertainty of the finest grid:
//
//   insufficient_grids  n < 4 (no least-squares fit is made)
//   unreliable          any of: f0 missing; n − 3 < 2 degrees of freedom;
//                       f0 outside [min f − k R_f, max f + k R_f];
//                       f0 behind the trend (data monotone with ≥ 3
//                       differences, f0 on the wrong side of the finest f);
//                       RDE_1 > rde_unreliable
//   converged           none of the above and all of: observed order p found
//                       with p_low ≤ p ≤ p_high; σ_RE/R_f < 1 (judged only
//                       with ≥ 2 degrees of freedom); RDE_1 ≤ rde_converged
//   pre-asymptotic      otherwise (suggests the next finer grid h_1 / r, r the
//                       series' mean refinement ratio (h_n/h_1)^(1/(n−1)))
//
// Constant data (method "constant") are converged: no grid error is visible.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "extrap/result.h"
#include "extrap/verdict_types.h"

namespace gridfree {

struct VerdictRules {
  double envelope_k = 3.0;       // f0 may lie at most k·R_f beyond the data
  double rde_converged = 0.05;   // finest-grid RDE for `converged`
  double rde_unreliable = 0.25;  // finest-grid RDE above which the series is `unreliable`
  int min_dof = 2;               // n − 3 degrees of freedom for `converged`
};

// Mean refinement ratio (h_max/h_min)^(1/(n−1)) of h ascending, n ≥ 2.
double mean_refinement_ratio(const std::vector<double>& h);

// `v` made `pre-asymptotic` for `why` (h ascending, n ≥ 2): its reasons
// become `why` followed by the advice to add the next finer grid, h_1/r,
// named with the case's `h_symbol` (ExtrapolationOptions::h_symbol).
void demote_to_pre_asymptotic(std::vector<std::string> why, const std::vector<double>& h, Verdict& v,
                              const std::string& h_symbol = "Δ*");

// The verdict of an extrapolation made with `opts` (only p_low, p_high are used).
Verdict judge(const ExtrapolationResult& r, const ExtrapolationOptions& opts,
              const VerdictRules& rules = {});

// For a series whose extrapolation could not be made at all: n < 4 gives
// insufficient_grids, otherwise unreliable with `why` as the reason.
Verdict verdict_without_fit(int n_grids, const std::string& why);

}  // namespace gridfree
