// SPDX-License-Identifier: GPL-3.0-or-later
// The report's charts, in display order; each chart has its own builder:
//   fig2_rde.svg                chart_rde.h (full page)
//   fig2_rde_<factor>.svg       chart_rde_bands.h (summary layout, report_layout.h)
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
#include "report/report_layout.h"
#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

struct NamedChart {
  std::string file;      // file name in the report folder
  std::string caption;   // one sentence for the Markdown/HTML
  Chart chart;
  std::vector<std::string> converted;  // PDF/PNG copies written beside the SVG (chart_export.h)
};

// The study-wide charts. Full page: fig2_rde.svg with a line per series and
// the speed-accuracy charts of every series. Summary layout: one RDE band
// chart per factor of 2 to 8 levels (one over all series when there is
// none), and speed-accuracy charts of the series speed_accuracy_selection
// picks, the chart's note saying which and of how many. p_low, p_high: the
// study's accepted order range (the Attention ranking).
std::vector<NamedChart> study_charts(const std::vector<SeriesSummary>& series, std::optional<double> target_rde,
                                     ReportLayout layout, double p_low, double p_high);

// The series a summary's speed-accuracy charts draw, one palette colour
// each: the `worst` first in the Attention ranking (series_concerns.h) that
// have an f0, then the `cheapest` converged series not already chosen — the
// least CPU time over their converged grids. Study order within each group.
std::vector<std::size_t> speed_accuracy_selection(const std::vector<SeriesSummary>& series, double p_low,
                                                  double p_high, std::size_t worst, std::size_t cheapest);

// Series i's Fig. 1 chart and (when it has GCI triplets) its GCI chart.
std::vector<NamedChart> series_charts(const std::vector<SeriesSummary>& series, std::size_t i);

// A full-page report's charts: study_charts, then every series' charts.
std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series,
                                      std::optional<double> target_rde = std::nullopt);

// Indices of at most `max` of n items, evenly spaced, first and last included.
std::vector<std::size_t> sample_indices(std::size_t n, std::size_t max);

}  // namespace gridfree
