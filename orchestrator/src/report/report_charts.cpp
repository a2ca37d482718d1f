// SPDX-License-Identifier: GPL-3.0-or-later
// The list of report charts (see report_charts.h).
#include "report/report_charts.h"

#include <algorithm>

#include "report/chart_common.h"
#include "report/chart_rde_bands.h"
#include "report/series_concerns.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

// The speed-accuracy charts recommend grids: written only when a converged
// series has a front to draw (chart_pareto.h). `note`: what was sampled.
void add_speed_accuracy(std::vector<NamedChart>& out, const std::vector<SeriesSummary>& series,
                        const std::string& note) {
  Chart cpu = speed_accuracy_chart(series, CostMeasure::cpu_seconds);
  if (!cpu.series.empty()) {
    if (!note.empty()) cpu.note = note + (cpu.note.empty() ? "" : ". " + cpu.note);
    out.push_back({"speed_accuracy.svg",
                   "CPU time against a-priori RDE: the Pareto front of each converged series connected, dominated "
                   "grids faded, series not converged hollow and never on a front; the cheapest grid for a target "
                   "RDE is the lowest front point left of it.",
                   std::move(cpu), {}});
  }
  // Machine-independent: cells × iterations, or the cells alone when the
  // case's results report no iterations (never a chart of zeros).
  const CaseVocabulary words = study_vocabulary(series);
  Chart work = speed_accuracy_chart(series, words.iterations_counted ? CostMeasure::cell_iterations : CostMeasure::cells);
  if (!work.series.empty()) {
    if (!note.empty()) work.note = note + (work.note.empty() ? "" : ". " + work.note);
    out.push_back({"speed_accuracy_work.svg",
                   words.iterations_counted
                       ? "The same with the machine-independent cost cells × " + words.iteration + "s."
                       : "The same against the number of cells, a machine-independent size: the code reports no "
                         "iteration counts, so cells × iterations cannot be formed.",
                   std::move(work), {}});
  }
}

}  // namespace

std::vector<std::size_t> sample_indices(std::size_t n, std::size_t max) {
  std::vector<std::size_t> out;
  if (n <= max) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  if (max == 1) return {0};
  for (std::size_t k = 0; k < max; ++k) out.push_back(k * (n - 1) / (max - 1));
  return out;
}

std::vector<std::size_t> speed_accuracy_selection(const std::vector<SeriesSummary>& series, double p_low,
                                                  double p_high, std::size_t worst, std::size_t cheapest) {
  std::vector<std::size_t> bad, out;
  for (const auto& c : series_concerns(series, p_low, p_high))
    if (bad.size() < worst && series[c.series].f0()) bad.push_back(c.series);
  std::vector<std::pair<double, std::size_t>> cost;
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (series[i].verdict != "converged" || std::find(bad.begin(), bad.end(), i) != bad.end()) continue;
    double cpu = 0;
    for (const GridPoint& g : series[i].series.grids)
      if (is_converged(g)) cpu += g.cpu_s;
    cost.emplace_back(cpu, i);
  }
  std::stable_sort(cost.begin(), cost.end());
  std::sort(bad.begin(), bad.end());
  out = bad;
  std::vector<std::size_t> cheap;
  for (std::size_t k = 0; k < cost.size() && k < cheapest; ++k) cheap.push_back(cost[k].second);
  std::sort(cheap.begin(), cheap.end());
  out.insert(out.end(), cheap.begin(), cheap.end());
  return out;
}

std::vector<NamedChart> study_charts(const std::vector<SeriesSummary>& series, std::optional<double> target_rde,
                                     ReportLayout layout, double p_low, double p_high) {
  std::vector<NamedChart> out;
  if (layout == ReportLayout::full_page) {
    const std::string reference = study_vocabulary(series).reference_rde;
    out.push_back({"fig2_rde.svg",
                   "RDE of every grid of every series (docs/PHYSICS.md §8): lower is better" +
                       (reference.empty() ? std::string(".") : "; " + reference + "."),
                   rde_chart(series, target_rde), {}});
    add_speed_accuracy(out, series, "");
    return out;
  }
  auto factors = band_factors(series);
  if (factors.empty()) factors.push_back("");
  for (const auto& factor : factors) {
    const std::string name = factor.empty() ? "all" : slugify(factor);
    out.push_back({"fig2_rde_" + name + ".svg",
                   "RDE of every grid (docs/PHYSICS.md §8), aggregated " +
                       (factor.empty() ? std::string("over all series") : "by " + factor) +
                       ": the median and the 10–90 % band at each " + study_vocabulary(series).h_symbol +
                       "; each series' grids with their RDE are in the grids "
                       "table of its page.",
                   rde_band_chart(series, factor, target_rde), {}});
  }
  // The series that most need a look and the cheapest converged ones, one
  // colour each (kSpeedAccuracyWorst + kSpeedAccuracyCheapest ≤ 7 palette
  // colours; the 8th is the legend's "dominated grid").
  const auto picked =
      speed_accuracy_selection(series, p_low, p_high, kSpeedAccuracyWorst, kSpeedAccuracyCheapest);
  std::vector<SeriesSummary> sample;
  for (std::size_t i : picked) sample.push_back(series[i]);
  const std::size_t n_worst =
      speed_accuracy_selection(series, p_low, p_high, kSpeedAccuracyWorst, 0).size();
  add_speed_accuracy(out, sample,
                     std::to_string(sample.size()) + " of " + std::to_string(series.size()) + " series drawn: " +
                         std::to_string(n_worst) + " that most need a look (Attention) and " +
                         std::to_string(sample.size() - n_worst) +
                         " cheapest converged (least CPU over their grids); every grid's cost and RDE in grids.csv");
  return out;
}

std::vector<NamedChart> series_charts(const std::vector<SeriesSummary>& series, std::size_t i) {
  std::vector<NamedChart> out;
  const std::string slug = series_slug(series[i], i);
  const CaseVocabulary words = series_vocabulary(series[i].series);
  out.push_back({"fig1_" + slug + ".svg",
                 words.quantity_symbol + " against " + words.h_symbol + " for " +
                     series[i].label + ", with the fits, f0 and U.",
                 series_chart(series[i], i), {}});
  if (series[i].extrapolation && !series[i].extrapolation->gci.empty()) {
    out.push_back({"gci_" + slug + ".svg",
                   "Classic three-grid extrapolation of every consecutive triplet for " + series[i].label +
                       ": its GCI band (marker = convergence type) and φ_ext, beside the regression.",
                   gci_chart(series[i], i), {}});
  }
  return out;
}

std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series, std::optional<double> target_rde) {
  auto out = study_charts(series, target_rde, ReportLayout::full_page, StudyReportData{}.p_low,
                          StudyReportData{}.p_high);
  for (std::size_t i = 0; i < series.size(); ++i)
    for (auto& c : series_charts(series, i)) out.push_back(std::move(c));
  return out;
}

}  // namespace gridfree
