// fig2_rde.svg (FM18 Fig. 2): RDE_i = U_i/|f0| in percent against Δ* for
// every grid of every series with an uncertainty (docs/PHYSICS.md §8). Both
// axes follow the report's axis rule: log when the data span more than a
// decade (chart_axis.h scale_for_span).
#pragma once

#include <vector>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

Chart rde_chart(const std::vector<SeriesSummary>& series);

}  // namespace gridfree
