// SPDX-License-Identifier: GPL-3.0-or-later
// The report's tables, built from the series summaries:
//   grids        one row per job (series, Δ*, cells, status, dp_star, U, RDE,
//                iterations, wall, cpu, RSS, reason)
//   series       one row per series: extrapolation (method, f0, p, c, c1, c2,
//                σ_RE, R_f, σ_RE/R_f and the good-fit flag σ_RE/R_f < 1, Fs, ng)
//   differences  one-factor pairs, 2|f0a − f0b|/|f0a + f0b|
//   gci          classic three-grid GCI of every consecutive triplet, beside f0
//   failures     grids that finished without a value, with the reason
//   coverage     the coverage self-check per series (series_coverage.h)
#pragma once

#include <functional>
#include <vector>

#include "report/differences.h"
#include "report/series_summary.h"
#include "report/table.h"

namespace gridfree {

Table grids_table(const std::vector<SeriesSummary>& series);
Table series_table(const std::vector<SeriesSummary>& series, double p_low, double p_high);
Table differences_table(const std::vector<SeriesSummary>& series,
                        const std::vector<SeriesDifference>& differences);
Table gci_table(const std::vector<SeriesSummary>& series, double p_low, double p_high);
Table failures_table(const std::vector<SeriesSummary>& series);
Table coverage_table(const std::vector<SeriesSummary>& series);

// The CSV of a per-series table made series by series (`of_series` of one
// series at a time): the same text as to_csv(of_series(series)) without
// holding every row as a Table (48 600 grids take 85 MB that way).
std::string csv_by_series(const std::vector<SeriesSummary>& series,
                          const std::function<Table(const std::vector<SeriesSummary>&)>& of_series);

}  // namespace gridfree
