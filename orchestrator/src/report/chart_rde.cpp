// SPDX-License-Identifier: GPL-3.0-or-later
// RDE vs Δ* of every series (see chart_rde.h).
#include "report/chart_rde.h"

#include "report/chart_common.h"
#include "report/text_format.h"

namespace gridfree {

Chart rde_chart(const std::vector<SeriesSummary>& series, std::optional<double> target_rde) {
  Chart chart;
  chart.id = "fig2-rde";
  chart.title = "Relative discretization error bound RDE = U/|f_{0}|";
  chart.subtitle = "series with at least 4 converged grids, each with its verdict (not converged: dashed, hollow); "
                   "log axes when the data span more than a decade";
  // External series: h as their study defines it (one h per study's cases).
  chart.x = series.empty() ? delta_star_axis() : delta_star_axis(series.front().series.h_axis());
  chart.y = rde_percent_axis();
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& s = series[i];
    if (!s.extrapolation) continue;
    // The verdict in the legend; a series that is not converged dashed and hollow.
    const bool converged = s.verdict == "converged";
    ChartSeries c{s.label + title_suffix(s) + " (" + (s.verdict.empty() ? "no verdict" : s.verdict) + ")",
                  {}, {}, {}, marker_for(int(i)), true, !converged, !converged, int(i)};
    for (const auto& g : s.extrapolation->grids) {
      if (!g.rde) continue;
      c.x.push_back(g.h);
      c.y.push_back(*g.rde * 100.0);
    }
    if (!c.x.empty()) chart.series.push_back(c);
  }
  if (target_rde) chart.hlines.push_back({*target_rde * 100.0, "target RDE " + format_percent(*target_rde), 6, true});
  if (chart.series.empty()) chart.note = "No series has an uncertainty yet (needs 4 converged grids).";
  return chart;
}

}  // namespace gridfree
