// The list of report charts (see report_charts.h).
#include "report/report_charts.h"

#include "report/chart_common.h"

namespace gridfree {

std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series, std::optional<double> target_rde) {
  std::vector<NamedChart> out;
  out.push_back({"fig2_rde.svg",
                 "RDE of every grid of every series (docs/PHYSICS.md §8): lower is better; FM18 found < 4% everywhere.",
                 rde_chart(series, target_rde), {}});
  // The speed-accuracy charts recommend grids: written only when a converged
  // series has a front to draw (chart_pareto.h).
  Chart cpu = speed_accuracy_chart(series, CostMeasure::cpu_seconds);
  if (!cpu.series.empty())
    out.push_back({"speed_accuracy.svg",
                   "CPU time against a-priori RDE: the Pareto front of each converged series connected, dominated "
                   "grids faded, series not converged hollow and never on a front; the cheapest grid for a target "
                   "RDE is the lowest front point left of it.",
                   std::move(cpu), {}});
  Chart work = speed_accuracy_chart(series, CostMeasure::cell_iterations);
  if (!work.series.empty())
    out.push_back({"speed_accuracy_work.svg",
                   "The same with the machine-independent cost cells × outer iterations.", std::move(work), {}});
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string slug = series_slug(series[i], i);
    out.push_back({"fig1_" + slug + ".svg", "DP* against Δ* for " + series[i].label + ", with the fits, f0 and U.",
                   series_chart(series[i], i), {}});
    if (series[i].extrapolation && !series[i].extrapolation->gci.empty()) {
      out.push_back({"gci_" + slug + ".svg",
                     "Classic three-grid extrapolation of every consecutive triplet for " + series[i].label +
                         ": its GCI band (marker = convergence type) and φ_ext, beside the regression.",
                     gci_chart(series[i], i), {}});
    }
  }
  return out;
}

}  // namespace gridfree
