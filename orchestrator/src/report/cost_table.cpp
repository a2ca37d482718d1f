// Target RDE → cheapest grid → its cost (see cost_table.h).
#include "report/cost_table.h"

#include <string>

#include "report/text_format.h"

namespace gridfree {

const GridPoint* cheapest_grid_for(const SeriesSummary& s, double target) {
  if (!s.extrapolation) return nullptr;
  const GridPoint* best = nullptr;
  for (const GridPoint& g : s.series.grids) {
    if (!is_converged(g)) continue;
    const ExtrapolatedGrid* e = s.extrapolation->grid_at(g.delta_star);
    if (!e || !e->rde || *e->rde > target) continue;
    if (!best || g.cpu_s < best->cpu_s) best = &g;
  }
  return best;
}

Table cost_table(const std::vector<SeriesSummary>& series, const std::vector<double>& targets) {
  Table t;
  t.columns = {{"series", {}, false, false},         {"verdict", {}, false, false},
               {"target_rde", "target RDE", false, true}, {"delta_star", "cheapest Δ*", false, true},
               {"cells", {}, false, true},           {"cell_iterations", "cells × iterations", false, true},
               {"cpu_s", "CPU s", false, true},      {"peak_rss_mb", "peak MB", false, true},
               {"rde", "its RDE", false, true}};
  for (const auto& s : series) {
    if (!s.f0()) continue;  // no extrapolated value, no RDE
    for (double target : targets) {
      const GridPoint* g = cheapest_grid_for(s, target);
      std::vector<Cell> row{text_cell(s.label), text_cell(s.verdict), percent_cell(target)};
      if (!g) {
        row.push_back(text_cell(kNoGridMeetsTarget));
        for (int k = 0; k < 5; ++k) row.push_back(text_cell(""));
      } else {
        const long long cells = static_cast<long long>(g->nx) * g->ny * g->nz;
        row.push_back(number_cell(g->delta_star, 4));
        row.push_back(integer_cell(cells));
        row.push_back(number_cell(static_cast<double>(cells) * g->iterations, 3));
        row.push_back(number_cell(g->cpu_s, 3));
        row.push_back(number_cell(g->peak_rss_mb, 3));
        row.push_back(percent_cell(s.extrapolation->grid_at(g->delta_star)->rde));
      }
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

}  // namespace gridfree
