// SPDX-License-Identifier: GPL-3.0-or-later
// The coverage self-check of a series in the report (extrap/self_check.h,
// docs/EXTRAPOLATION.md "Coverage self-check"): made once a series has all
// its grids and at least 6 of them converged, through the report's
// Extrapolator seam; shown as a table, a summary line and, below the
// promised rate, a warning in the attention list.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/self_check.h"
#include "report/extrap_view.h"
#include "report/extrapolator.h"

namespace gridfree {

struct SeriesSummary;

// The numbers the check needs from the report's view of an extrapolation.
WindowFit window_fit(const ExtrapolationView& view);

// The check of converged grids (h, f in any order) whose whole extrapolation
// (the contract JSON) is `whole`; nothing with fewer than 6 grids or no f0.
std::optional<CoverageCheck> coverage_of(const std::vector<double>& h, const std::vector<double>& f,
                                         const nlohmann::json& whole, const Extrapolator& extrapolate);

// The check of one series in a report: the one stored when the series
// finished (SeriesData::stored_coverage), else made now; nothing when it has
// pending grids, fewer than 6 converged grids or no extrapolation.
std::optional<CoverageCheck> series_coverage(const SeriesSummary& s, const Extrapolator& extrapolate);

// "Δ* 3.3–1.93 (1.7 U₁)" for every window that missed, coarsest first;
// `h_symbol` the case's (study/case_vocabulary.h).
std::string missed_windows(const CoverageCheck& c, const std::string& h_symbol = "Δ*");
// The largest |f0_ref − f_1w| / U_1w over the judged windows.
std::optional<double> worst_distance(const CoverageCheck& c);
// covered / judged, empty without judged windows.
std::optional<double> coverage_rate(const CoverageCheck& c);

// Why no series has the check: "not yet made (…)" while grids are still to
// run, else "not made, and it cannot be with these grids: …" (a finished
// study of 5-grid series never has it).
std::string coverage_not_made(const std::vector<SeriesSummary>& series);

// "Coverage self-check" for the summary: totals over the checked series.
std::string coverage_summary(const std::vector<SeriesSummary>& series);

// One sentence per series below the promised rate, for the attention list.
std::vector<std::string> coverage_warnings(const std::vector<SeriesSummary>& series);

}  // namespace gridfree
