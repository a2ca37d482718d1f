// SPDX-License-Identifier: GPL-3.0-or-later
// What a study page shows of its verdicts when it has too many series to
// list them all (report_layout.h): how many series got each verdict, over
// the study and per factor level, and which series are the worst.
#pragma once

#include <cstddef>
#include <vector>

#include "report/series_summary.h"
#include "report/table.h"

namespace gridfree {

// verdict_counts.csv: a row for all series, then one per level of every
// factor with 2 to kShownRows levels (series_factors order); columns
// factor, level, series, then one per verdict word (converged,
// pre-asymptotic, unreliable, insufficient_grids, then any other word in
// order of appearance) and incomplete (series with pending grids).
Table verdict_count_table(const std::vector<SeriesSummary>& series);

// Indices of at most `max` series, worst first: by verdict (no verdict,
// insufficient_grids and unreliable, then pre-asymptotic, then converged),
// then by the finest grid's RDE, largest first (none counts as largest),
// then in study order.
std::vector<std::size_t> worst_series(const std::vector<SeriesSummary>& series, std::size_t max);

}  // namespace gridfree
