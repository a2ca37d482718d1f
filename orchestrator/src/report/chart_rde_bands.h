// SPDX-License-Identifier: GPL-3.0-or-later
// fig2_rde_<factor>.svg, the RDE chart of a study too large for one line
// per series (report_layout.h): per level of one factor, at every Δ* the
// median RDE over the level's series that have an RDE there (solid line with
// markers, legend "drag = bvk (n series)") and the 10th and 90th percentiles
// (dashed, the same colour, no legend entry). Δ* values equal to 4
// significant digits are one grid. Percentiles interpolate linearly between
// order statistics (quantile() below). Every series' RDE stays in grids.csv.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

// The q-quantile (0 ≤ q ≤ 1) of ascending `sorted` values, interpolated
// linearly between order statistics (Hyndman & Fan type 7); NaN when empty.
double quantile(const std::vector<double>& sorted, double q);

// Factors with 2 to 8 levels among the series (series_factors order); a
// factor with more levels (e.g. the cases of an ensemble) makes an
// unreadable band chart and is left out.
std::vector<std::string> band_factors(const std::vector<SeriesSummary>& series);

// The chart for one factor; an empty factor: one band over all series.
Chart rde_band_chart(const std::vector<SeriesSummary>& series, const std::string& factor,
                     std::optional<double> target_rde);

}  // namespace gridfree
