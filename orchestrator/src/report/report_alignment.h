// SPDX-License-Identifier: GPL-3.0-or-later
// The report's alignment section (docs/REPORTS.md, docs/TRANSFER.md
// "Alignment check"): per series and checked grid, the spread
//
//   s = (max dp* − min dp*) / mean dp*   over the grid and its variants
//
// (only when every one converged, and there are at least two) beside the
// grid's relative uncertainty U/|f| from the series' extrapolation. A grid
// whose spread exceeds U/|f| gets a warning: its U understates how much dp*
// depends on the grid there.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/alignment_data.h"
#include "report/series_summary.h"
#include "report/table.h"

namespace gridfree {

// The spread rule above; empty when a value is missing or fewer than two.
std::optional<double> alignment_spread(const std::vector<std::optional<double>>& dp_star);

struct AlignmentLine {
  std::string series_label;
  AlignmentGrid grid;
  std::optional<double> spread;
  std::optional<double> u_relative;  // U/|f| of this grid, when the series has an uncertainty
  bool exceeds() const { return spread && u_relative && *spread > *u_relative; }
};

std::vector<AlignmentLine> alignment_lines(const std::vector<AlignmentGrid>& grids,
                                           const std::vector<SeriesSummary>& series);

Table alignment_table(const std::vector<AlignmentLine>& lines);

// One sentence per grid whose spread exceeds U/|f|, for the attention list.
std::vector<std::string> alignment_warnings(const std::vector<AlignmentLine>& lines);

// How to read the section.
std::string alignment_reading_note();

}  // namespace gridfree
