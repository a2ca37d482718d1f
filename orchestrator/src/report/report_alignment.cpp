// SPDX-License-Identifier: GPL-3.0-or-later
// The report's alignment section (report_alignment.h).
#include "report/report_alignment.h"

#include <algorithm>
#include <cmath>

#include "extrap/value_format.h"
#include "report/text_format.h"

namespace gridfree {

std::optional<double> alignment_spread(const std::vector<std::optional<double>>& dp) {
  if (dp.size() < 2) return std::nullopt;
  double lo = 0, hi = 0, sum = 0;
  for (std::size_t i = 0; i < dp.size(); ++i) {
    if (!dp[i] || !std::isfinite(*dp[i])) return std::nullopt;
    lo = i == 0 ? *dp[i] : std::min(lo, *dp[i]);
    hi = i == 0 ? *dp[i] : std::max(hi, *dp[i]);
    sum += *dp[i];
  }
  const double mean = sum / static_cast<double>(dp.size());
  if (mean == 0) return std::nullopt;
  return (hi - lo) / std::abs(mean);
}

std::vector<AlignmentLine> alignment_lines(const std::vector<AlignmentGrid>& grids,
                                           const std::vector<SeriesSummary>& series) {
  std::vector<AlignmentLine> out;
  for (const auto& s : series) {
    for (const auto& g : grids) {
      if (g.series_id != s.series.id) continue;
      AlignmentLine line{s.label, g, alignment_spread(g.dp_star), std::nullopt};
      if (s.extrapolation)
        if (const ExtrapolatedGrid* e = s.extrapolation->grid_at(g.delta_star); e && e->u && e->f != 0)
          line.u_relative = *e->u / std::abs(e->f);
      out.push_back(std::move(line));
    }
  }
  return out;
}

Table alignment_table(const std::vector<AlignmentLine>& lines) {
  Table t;
  t.columns = {{"series", "Series"},
               {"grid_index", "grid", true, true},
               {"delta_star", "Δ*", false, true},
               {"cells", "cells"},
               {"variants", "alignments", false, true},
               {"dp_star_min", "DP* min", false, true},
               {"dp_star_max", "DP* max", false, true},
               {"spread", "spread", false, true},
               {"u_relative", "U/|f|", false, true},
               {"spread_exceeds_u", "spread > U"}};
  for (const auto& l : lines) {
    std::optional<double> lo, hi;
    for (const auto& v : l.grid.dp_star)
      if (v) {
        lo = lo ? std::min(*lo, *v) : *v;
        hi = hi ? std::max(*hi, *v) : *v;
      }
    const auto& c = l.grid.cells;
    t.rows.push_back({text_cell(l.series_label), integer_cell(l.grid.grid_index),
                      number_cell(l.grid.delta_star, 4),
                      text_cell(std::to_string(c[0]) + "×" + std::to_string(c[1]) + "×" + std::to_string(c[2])),
                      integer_cell(static_cast<long long>(l.grid.dp_star.size())), number_cell(lo, 7),
                      number_cell(hi, 7), percent_cell(l.spread), percent_cell(l.u_relative),
                      text_cell(!l.spread || !l.u_relative ? "" : l.exceeds() ? "yes" : "no")});
  }
  return t;
}

std::vector<std::string> alignment_warnings(const std::vector<AlignmentLine>& lines) {
  std::vector<std::string> out;
  for (const auto& l : lines)
    if (l.exceeds())
      out.push_back(l.series_label + ": at Δ* = " + format_cell_size(l.grid.delta_star) + " the alignment spread " +
                    format_percent(l.spread) + " exceeds U/|f| = " + format_percent(l.u_relative) +
                    "; this grid's U understates its grid error (see Alignment check).");
  return out;
}

std::string alignment_reading_note() {
  return "Each checked grid was also solved with its cell counts changed by a few cells, so that the bed's "
         "features fall at other places inside a cell. The spread is (max − min)/mean of DP* over the grid and "
         "these re-aligned variants (shown only when all converged): the part of the grid error that "
         "extrapolation over one alignment cannot see. The variants are not part of the extrapolation. Compare "
         "it with the grid's U/|f|: where the spread is larger, that U understates the grid error and the "
         "series' uncertainty should not be trusted at that cell size (docs/TRANSFER.md).";
}

}  // namespace gridfree
