// SPDX-License-Identifier: GPL-3.0-or-later
// What needs a look in a study, series by series, ranked by how much it
// matters (docs/REPORTS.md "Attention"): the report's first screen lists
// them, linked, and the series table's filter finds every one of them
// (`attention:yes`), so no row cap hides a troubled series.
//
// Concerns and their weights (a series ranks by its heaviest, then by the
// sum, then by the finest grid's RDE, then in study order):
//   50  no f0, or the verdict unreliable / insufficient_grids
//   40  the coverage self-check missed (U₁ covered fewer windows than promised)
//   30  failed grids (any finished grid without a value: diverged, stalled, …)
//   20  the verdict pre-asymptotic
//   15  the observed order p outside the study's declared range
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "report/series_summary.h"

namespace gridfree {

struct SeriesConcerns {
  std::size_t series = 0;              // index into the study's series
  int weight = 0, total = 0;           // heaviest concern, sum of weights
  std::vector<std::string> concerns;   // "2 failed grids (1 diverged, 1 stalled)", …
  std::vector<std::string> words;      // filter words: failed stalled coverage no-f0 …
};

// Every series with at least one concern, ranked; p_low, p_high: the
// study's accepted range of the order.
std::vector<SeriesConcerns> series_concerns(const std::vector<SeriesSummary>& series, double p_low, double p_high);

}  // namespace gridfree
