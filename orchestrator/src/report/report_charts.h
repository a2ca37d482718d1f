// The report's charts (PHYSICS.md §8–§9), as Chart objects:
//   fig1_NN_<series>.svg  DP* vs Δ* for one series with the power-law
//                         (f0 + c h^p) and mixed-order (f0 + c1 h + c2 h²)
//                         fits, f0 as a dashed line and U as error bars;
//                         failed / not converged / pending grids drawn with
//                         their own markers (on the axis when they have no value)
//   fig2_rde.svg          RDE_i = U_i/|f0| vs Δ* for every series
//   speed_accuracy.svg    CPU time vs |f_i − f0|/|f0| of every converged job,
//                         log–log, one curve per series
//   gci_NN_<series>.svg   three-grid GCI φ_ext of every consecutive triplet
//                         beside the regression's f_i ± U_i and f0
#pragma once

#include <string>
#include <vector>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

struct NamedChart {
  std::string file;      // file name in the report folder
  std::string caption;   // one sentence for the Markdown/HTML
  Chart chart;
  std::vector<std::string> converted;  // PDF/PNG copies written beside the SVG (chart_export.h)
};

Chart series_chart(const SeriesSummary& series, std::size_t index);
Chart rde_chart(const std::vector<SeriesSummary>& series);
Chart speed_accuracy_chart(const std::vector<SeriesSummary>& series);
// A chart with no series when the series has no GCI triplet.
Chart gci_chart(const SeriesSummary& series, std::size_t index);

// All charts of a report, in display order: the two overview charts, then
// per series its Fig. 1 chart and (when it has GCI triplets) its GCI chart.
std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series);

}  // namespace gridfree
