// SPDX-License-Identifier: GPL-3.0-or-later
// The verdict of one series and the numbers its rules looked at
// (docs/EXTRAPOLATION.md "Verdicts"; computed by judge() in verdict.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gridfree {

// The numbers each rule looked at (empty when they cannot be computed).
struct VerdictChecks {
  int n_grids = 0, dof = 0;
  std::optional<double> envelope_low, envelope_high;  // min f − k R_f, max f + k R_f
  std::optional<double> rde_finest, sigma_over_range, p;
  // good_fit: σ_RE/R_f < 1 with at least min_dof degrees of freedom (fewer
  // cannot judge the fit). monotone: every grid-to-grid difference has one
  // sign (≥ 3 differences); behind_trend: then f0 lies on the wrong side of
  // the finest value.
  bool order_in_range = false, good_fit = false, inside_envelope = false;
  bool monotone = false, behind_trend = false;
};

struct Verdict {
  std::string value;                 // converged | pre-asymptotic | unreliable | insufficient_grids
  std::vector<std::string> reasons;  // in words, each naming the rule and its numbers
  std::optional<double> next_h;      // suggested finer grid (pre-asymptotic, unreliable, insufficient)
  VerdictChecks checks;
};

}  // namespace gridfree
