// SPDX-License-Identifier: GPL-3.0-or-later
// fig2_rde.svg (FM18 Fig. 2): RDE_i = U_i/|f0| in percent against Δ* for
// every grid of every series with an uncertainty (docs/PHYSICS.md §8). Both
// axes follow the report's axis rule: log when the data span more than a
// decade (chart_axis.h scale_for_span).
#pragma once

#include <optional>
#include <vector>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

// With a target (the study's grids.target_rde, a fraction), a dashed black
// line at it, labelled "target RDE …".
Chart rde_chart(const std::vector<SeriesSummary>& series, std::optional<double> target_rde = std::nullopt);

}  // namespace gridfree
