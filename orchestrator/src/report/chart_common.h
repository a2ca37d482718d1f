// SPDX-License-Identifier: GPL-3.0-or-later
// Pieces shared by the report's chart builders (chart_series.cpp,
// chart_rde.cpp, chart_gci.cpp, chart_pareto.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

// "01_PC1_superbee_fwhm6_bvk": the series' file-name stem.
std::string series_slug(const SeriesSummary& s, std::size_t index);
// " (incomplete)" while grids are pending, else "".
std::string title_suffix(const SeriesSummary& s);
// The Δ* axis: linear from 0, log when the grids span more than a decade.
ChartAxis delta_star_axis(std::string label = "Δ* (cell size / particle diameter)");
// The RDE axis in percent: linear from 0, log when the data span more than a decade.
ChartAxis rde_percent_axis();
// U_1 of the series' finest grid (an interval about f_1, not about f0), if any.
std::optional<double> finest_u(const SeriesSummary& s);
// "f_{0} = 1017.0": f0 rounded to the digits U_1 supports (text_format.h),
// without ± — U_1 belongs to the finest grid's f_1, f0 has no uncertainty of its own.
std::string f0_label(const SeriesSummary& s);
// "f_{1} = 1018.2 ± 1.5 (finest Δ* = 0.5)": the finest grid's value with its
// own U_1; empty without an extrapolated finest grid.
std::string finest_label(const SeriesSummary& s);

}  // namespace gridfree
