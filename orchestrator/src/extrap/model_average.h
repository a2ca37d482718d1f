// SPDX-License-Identifier: GPL-3.0-or-later
// The default method `averaged` (docs/EXTRAPOLATION.md "Default procedure"):
// the capped fit's answer and uncertainty, widened to hold the spread of f0
// over every admissible error expansion. Measured on the development corpus
// (bench/coverage/corpus.py) against capped, fm, eh14 and other candidates.
//
//   fits    the chosen (capped) fit and Eça & Hoekstra's four expansions
//           f0 + α h^p, f0 + α h, f0 + α h², f0 + α1 h + α2 h² (each the
//           weighted or unweighted variant with the smaller σ, eh14.h);
//   admissible: σ_k < R_f (the fit describes the data), and for the power
//           law an order found;
//   widen   U_i ≥ 1.25 max_k |f0_k − f_i| + σ_RE for every grid,
//           U₀  = U₀ + 1.25 max_k |f0_k − f0|;
//   unreliable: a window the verdict calls `unreliable` (the fits do not
//           describe it) keeps U_i, U₀ ≥ 3 Δφ, Δφ = (f_max − f_min)/(n − 1)
//           Eça & Hoekstra's data range parameter and 3 their safety factor
//           for a fit that fails their criteria (eh14.h).
#pragma once

#include <string>
#include <vector>

#include "extrap/result.h"
#include "extrap/series.h"

namespace gridfree {

// f0 of every admissible fit (the chosen one first) and their names.
using ModelSpread = ModelSpreadSummary;

ModelSpread admissible_fits(const Series& s, const ExtrapolationOptions& opts, const ExtrapolationResult& chosen);

// U_i ≥ factor · max_k |v_k − f_i| + σ_RE for every grid (RDE follows U).
void widen_to_hold(const std::vector<double>& values, double factor, ExtrapolationResult& out);

// U₀ = U₀ + 1.25 max_k |v_k − f0| (U₀ already set).
void widen_u0_to_hold(const std::vector<double>& values, ExtrapolationResult& out);

// Safety factor on the data range Δφ for an `unreliable` result.
inline constexpr double kUnreliableRangeFactor = 3.0;

// U_i ≥ 3 Δφ for every grid and U₀ ≥ 3 Δφ (RDE follows U), with a note; for
// a result whose verdict is `unreliable`.
void floor_unreliable_to_data_range(const Series& s, ExtrapolationResult& out);

// The `averaged` method: fm_extrapolate with the order capped, then the
// widening above; out.model_spread records the fits. n ≥ 4, f not constant.
void averaged_extrapolate(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out);

}  // namespace gridfree
