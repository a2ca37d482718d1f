// SPDX-License-Identifier: GPL-3.0-or-later
// Per-series digest for the report: grids sorted by Δ*, the converged
// (h, f) pairs that go to the extrapolation, counts of failed and pending
// grids, and the extrapolation itself (PHYSICS.md §8) when it could be made.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "extrap/self_check.h"
#include "report/extrap_view.h"
#include "report/extrapolator.h"
#include "report/report_data.h"

namespace gridfree {

inline constexpr int kMinGridsForUncertainty = 4;  // PHYSICS.md §8: ng ≥ 4

// A grid with a usable value: status converged and a dp_star.
bool is_converged(const GridPoint& grid);
// A grid not yet finished: queued or running (no result yet).
bool is_pending(const GridPoint& grid);
// A grid that finished without a usable value (any other status).
bool is_failed(const GridPoint& grid);

struct SeriesSummary {
  SeriesData series;                  // grids sorted by Δ* ascending (finest first)
  std::string label;
  std::vector<double> h, f;           // converged grids, h ascending
  int failed = 0, pending = 0;
  bool incomplete = false;            // pending grids, or series status queued/running
  std::optional<ExtrapolationView> extrapolation;
  std::string extrapolation_error;    // why there is no extrapolation, if there is none
  // docs/EXTRAPOLATION.md "Verdicts": the extrapolation's verdict, or (no
  // extrapolation) insufficient_grids / unreliable from the converged count.
  std::string verdict;
  std::vector<std::string> verdict_reasons;
  std::optional<CoverageCheck> coverage;  // the coverage self-check, once made (series_coverage.h)

  int converged() const { return static_cast<int>(h.size()); }
  bool insufficient() const { return converged() < kMinGridsForUncertainty; }
  std::optional<double> f0() const;   // the chosen extrapolated value, if any
  // |f − f0| / |f0|: the error of one grid value against the extrapolation.
  std::optional<double> relative_error(double f) const;
  // The extrapolation's entry (U, RDE, fitted value) of a converged grid of
  // this series; null when the grid did not converge or there is no extrapolation.
  const ExtrapolatedGrid* extrapolated(const GridPoint& grid) const;
  // "insufficient grids (3 converged, 4 needed); incomplete (2 of 5 pending)", or "".
  std::string note() const;
};

// One summary per series, in the data's order. The extrapolator is called
// for every series with at least one converged grid; its exceptions are
// caught and recorded in extrapolation_error.
std::vector<SeriesSummary> summarize_series(const StudyReportData& data, const Extrapolator& extrapolate);

}  // namespace gridfree
