// SPDX-License-Identifier: GPL-3.0-or-later
// The fit window of an adaptive series (docs/EXTRAPOLATION.md "Adaptive
// series"): when the fit on all n converged grids is not `converged`, the
// coarse grids may lie outside the asymptotic range and spoil every fit that
// keeps them. Then the finest k grids are fitted, k = n−1, n−2, …, 5 (never
// fewer than 5, so that a `converged` verdict keeps its two degrees of
// freedom, n − 3 ≥ 2), and the first window whose verdict is `converged` is
// used. When none is, the fit on all n grids stands. With n < 6 no window
// exists: the full set is the only candidate.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/extrapolator.h"

namespace gridfree {

struct WindowedFit {
  nlohmann::json extrapolation;   // the fit that is used (docs/INTERFACE.md §4)
  std::size_t used = 0;           // grids in that fit (the finest `used` ones)
  std::size_t left_out = 0;       // coarser grids left out (0: all used)
  double finest_h = 0, coarsest_used_h = 0;
  std::string full_set_verdict;   // verdict of the fit on all grids ("" when none)
};

// Smallest window: 5 grids (min_dof 2 of extrap/verdict.h plus three parameters).
inline constexpr std::size_t kMinWindowGrids = 5;

// The rule above on the converged grids (h, f) in any order; `extrapolate`
// is the study's extrapolator. Needs h.size() ≥ 2.
WindowedFit windowed_extrapolation(const std::vector<double>& h, const std::vector<double>& f,
                                   const Extrapolator& extrapolate);

// "" when every grid was used, else e.g. "fit on the 5 finest grids, Δ* 1.35
// → 0.553; the 3 coarser ones were left out (the fit on all 8 was
// pre-asymptotic)".
std::string window_sentence(const WindowedFit& w, const std::string& h_symbol = "Δ*");

// An Extrapolator that applies the rule and returns the window's JSON, so the
// stored extrapolation and verdict of an adaptive series are the window's.
Extrapolator windowed_extrapolator(Extrapolator base);

}  // namespace gridfree
