// SPDX-License-Identifier: GPL-3.0-or-later
// Target RDE → cheapest grid → its cost (see cost_table.h).
#include "report/cost_table.h"

#include <algorithm>
#include <optional>
#include <string>

#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

// The grid's a-priori RDE, or null when it has none (not converged, or no U).
std::optional<double> rde_of(const SeriesSummary& s, const GridPoint& g) {
  const ExtrapolatedGrid* e = s.extrapolated(g);
  return e ? e->rde : std::nullopt;
}

// The grid and every finer grid with an RDE meet the target.
bool meets_down_to_the_finest(const SeriesSummary& s, const GridPoint& g, double target) {
  return std::all_of(s.series.grids.begin(), s.series.grids.end(), [&](const GridPoint& finer) {
    if (finer.delta_star > g.delta_star) return true;
    const auto rde = rde_of(s, finer);
    return !rde || *rde <= target;
  });
}

}  // namespace

const GridPoint* cheapest_grid_for(const SeriesSummary& s, double target) {
  if (!s.extrapolation) return nullptr;
  const GridPoint* best = nullptr;
  for (const GridPoint& g : s.series.grids) {
    if (!rde_of(s, g) || !meets_down_to_the_finest(s, g, target)) continue;
    if (!best || g.cpu_s < best->cpu_s) best = &g;
  }
  return best;
}

Table cost_table(const std::vector<SeriesSummary>& series, const std::vector<double>& targets) {
  Table t;
  const CaseVocabulary words = study_vocabulary(series);  // an external study's declared h
  t.columns = {{"series", {}, false, false},         {"verdict", {}, false, false},
               {"target_rde", "target RDE", false, true},
               Column{words.h_column, "cheapest " + words.h_symbol, false, true},
               {"cells", {}, false, true},           {"cell_iterations", "cells × iterations", false, true},
               {"cpu_s", "CPU s", false, true},      {"peak_rss_mb", "peak MB", false, true},
               {"rde", "its RDE", false, true}};
  for (const auto& s : series) {
    if (!s.f0()) continue;  // no extrapolated value, no RDE
    for (double target : targets) {
      // Only a converged series names a grid: the others' RDEs may still move.
      const bool converged = s.verdict == "converged";
      const GridPoint* g = converged ? cheapest_grid_for(s, target) : nullptr;
      std::vector<Cell> row{text_cell(s.label), text_cell(s.verdict), percent_cell(target)};
      if (!converged) {
        row.push_back(text_cell("— (series " + (s.verdict.empty() ? std::string("without verdict") : s.verdict) + ")"));
        for (int k = 0; k < 5; ++k) row.push_back(text_cell(""));
      } else if (!g) {
        row.push_back(text_cell(kNoGridMeetsTarget));
        for (int k = 0; k < 5; ++k) row.push_back(text_cell(""));
      } else {
        const long long cells = static_cast<long long>(g->nx) * g->ny * g->nz;
        row.push_back(number_cell(g->delta_star, 4));
        row.push_back(integer_cell(cells));
        // Empty when the code reports no iterations: never a product of 0.
        row.push_back(words.iterations_counted ? number_cell(static_cast<double>(cells) * g->iterations, 3)
                                               : text_cell(""));
        row.push_back(number_cell(g->cpu_s, 3));
        row.push_back(number_cell(g->peak_rss_mb, 3));
        row.push_back(percent_cell(rde_of(s, *g)));
      }
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

}  // namespace gridfree
