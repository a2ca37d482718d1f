// SPDX-License-Identifier: GPL-3.0-or-later
// Tests a fit cannot make on its own scatter: whether the data agree with the
// formal order the user declared, and whether the series agrees with itself
// when one end is left out (docs/EXTRAPOLATION.md "Bias checks"). Both look
// for the error every window of a series shares, which the coverage
// self-check (self_check.h) cannot see.
//
//   declared order P (ExtrapolationOptions::expected_order), observed p:
//     ratio  q = p / P
//     factor FS = 2.45 − 0.85 q (0 < q ≤ 1), 16.4 q − 14.8 (q > 1)
//            [Xing & Stern, J. Fluids Eng. 132 (2010) 061403]
//     every U_i ≥ FS |f0 − f_i| + σ_RE,  U₀ ≥ FS |f0 − f_1| + σ_RE
//     consistent when |q − 1| ≤ order_tolerance; p not found is inconsistent
//   leave-one-out (n ≥ 6): f0 of the series without its coarsest grid and
//     without its finest, same method and settings;
//     agree when both lie within U₀ of f0; every U_i and U₀ then grow to
//     hold both: U_i ≥ 1.25 |f0_k − f_i| + σ_RE, U₀ ≥ U₀ + 1.25 |f0_k − f0|
//     (U₀ on the right: before growing)
//
// A series that fails either test is not `converged` (verdict becomes
// `pre-asymptotic` with the test's numbers as its reason).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/result.h"
#include "extrap/series.h"

namespace gridfree {

struct BiasRules {
  double order_tolerance = 0.25;  // |p/P − 1| accepted as "the declared order"
  // Each leave-one-out fit keeps ≥ 5 grids: a 4-grid fit has one degree of
  // freedom and cannot be judged itself (Verdicts), so it cannot judge another.
  std::size_t min_grids_loo = 6;
};

// Xing & Stern's factor of safety for q = p_observed / p_declared > 0.
double xing_stern_factor(double q);

// f0 of a sub-series with the same method and settings (empty: no f0).
using SubSeriesF0 = std::function<std::optional<double>(const Series&)>;

// Fills out.bias and widens out.grids[].u, .rde and out.u0 as above (before
// the verdict is judged, so the RDE rules see the wider U). Returns the
// reason of every failed test (empty: none failed or none applied).
std::vector<std::string> apply_bias_checks(const Series& s, const ExtrapolationOptions& opts,
                                           const SubSeriesF0& refit, ExtrapolationResult& out,
                                           const BiasRules& rules = {});

// A `converged` verdict with a failed test becomes `pre-asymptotic`, the
// tests' reasons first, and names the next finer grid h_1/r; any other
// verdict gets the reasons added. h ascending.
void demote_for_bias(const std::vector<std::string>& failed, const std::vector<double>& h, Verdict& v,
                     const std::string& h_symbol = "Δ*");

nlohmann::ordered_json to_ordered_json(const BiasCheck& b);

}  // namespace gridfree
