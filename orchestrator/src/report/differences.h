// SPDX-License-Identifier: GPL-3.0-or-later
// Relative differences of the extrapolated values between series that
// differ in exactly one factor (case, convection, fwhm_dp, drag,
// deposition) — how FM18 compares drag laws, filter widths and particle
// configurations:
//
//     d_ab = 2 |f0_a − f0_b| / |f0_a + f0_b|
//
// and whether the difference exceeds the combined uncertainty of the two
// series (docs/EXTRAPOLATION.md "Comparing series"):
//
//     U_ab = sqrt(U_a² + U_b²),  U_x = U of series x's finest grid,
//     significant ⇔ |f0_a − f0_b| > U_ab
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/series_summary.h"

namespace gridfree {

struct SeriesDifference {
  std::string factor;             // case | convection | fwhm_dp | drag | deposition | an external study's factor
  std::string value_a, value_b;   // that factor's level in series a and b
  std::size_t a = 0, b = 0;       // indices into the summaries (a < b)
  std::optional<double> f0_a, f0_b;
  std::optional<double> relative; // d_ab; empty when either f0 is missing
  std::optional<double> u_a, u_b;  // U of each series' finest grid
  std::optional<double> u_combined;      // sqrt(U_a² + U_b²)
  std::optional<double> u_relative;      // 2 U_ab / |f0_a + f0_b|, comparable with d_ab
  std::optional<bool> exceeds_u;         // |f0_a − f0_b| > U_ab
  std::string verdict_a, verdict_b;      // the two series' verdicts
  bool both_converged() const { return verdict_a == "converged" && verdict_b == "converged"; }
};

// U of a series' finest converged grid, if it has one.
std::optional<double> finest_uncertainty(const SeriesSummary& s);

// 2|a − b| / |a + b|; empty when a + b = 0 or either is not finite.
std::optional<double> relative_difference(double a, double b);

// (factor, level) pairs of a series, in the fixed order case, convection,
// fwhm_dp, drag, deposition (an empty deposition counts as "diffusion");
// an external series': case, then the study's own factors in name order.
// Series pair only with series of their own quantity.
std::vector<std::pair<std::string, std::string>> series_factors(const SeriesData& series);

// A factor of more levels than this pairs no series: the instances of a
// large ensemble (150 cases × 18 series make 200 000 pairs, a 48 MB table
// nobody reads); their spread is the ensemble section's (report_ensembles.h).
inline constexpr std::size_t kMaxPairedLevels = 12;

// Every pair of series differing in exactly one factor of at most
// kMaxPairedLevels levels, in series order.
std::vector<SeriesDifference> one_factor_differences(const std::vector<SeriesSummary>& series);

}  // namespace gridfree
