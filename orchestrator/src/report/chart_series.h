// SPDX-License-Identifier: GPL-3.0-or-later
// fig1_NN_<series>.svg (FM18 Fig. 1): DP* vs Δ* for one series with the
// power-law (f0 + c h^p) and mixed-order (f0 + c1 h + c2 h²) fits of
// docs/PHYSICS.md §8, f0 ± U as a dashed line and U as error bars, every
// converged point labelled with its Δ*; the chosen fit in full colour, the
// other faded and labelled "rejected"; failed / not converged / pending
// grids with their own markers (on the axis when they have no value).
#pragma once

#include <cstddef>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

Chart series_chart(const SeriesSummary& series, std::size_t index);

}  // namespace gridfree
