// The report's charts, in display order; each chart has its own builder:
//   fig2_rde.svg                chart_rde.h
//   speed_accuracy.svg          chart_pareto.h (CPU time)
//   speed_accuracy_work.svg     chart_pareto.h (cells × iterations)
//   fig1_NN_<series>.svg        chart_series.h
//   gci_NN_<series>.svg         chart_gci.h
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/chart_gci.h"
#include "report/chart_pareto.h"
#include "report/chart_rde.h"
#include "report/chart_series.h"
#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

struct NamedChart {
  std::string file;      // file name in the report folder
  std::string caption;   // one sentence for the Markdown/HTML
  Chart chart;
  std::vector<std::string> converted;  // PDF/PNG copies written beside the SVG (chart_export.h)
};

// All charts of a report: the overview charts, then per series its Fig. 1
// chart and (when it has GCI triplets) its GCI chart.
std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series,
                                      std::optional<double> target_rde = std::nullopt);

}  // namespace gridfree
