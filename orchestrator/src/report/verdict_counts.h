// SPDX-License-Identifier: GPL-3.0-or-later
// What a study page shows of its verdicts when it has too many series to
// list them all (report_layout.h): how many series got each verdict, over
// the study and per factor level (the series that need a look are ranked by
// series_concerns.h).
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

}  // namespace gridfree
