// SPDX-License-Identifier: GPL-3.0-or-later
// RDE bands per factor level (see chart_rde_bands.h).
#include "report/chart_rde_bands.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "report/chart_common.h"
#include "report/differences.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

constexpr std::size_t kMaxBandLevels = 8;

std::string level_of(const SeriesSummary& s, const std::string& factor) {
  for (const auto& [name, level] : series_factors(s.series))
    if (name == factor) return level;
  return {};
}

// Δ* to 4 significant digits: the same grid of different series.
double grid_key(double h) { return std::stod(format_g(h, 4)); }

}  // namespace

double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (pos - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

std::vector<std::string> band_factors(const std::vector<SeriesSummary>& series) {
  std::vector<std::string> out;
  if (series.empty()) return out;
  for (const auto& [name, unused] : series_factors(series.front().series)) {
    std::vector<std::string> levels;
    for (const auto& s : series) {
      const std::string level = level_of(s, name);
      if (std::find(levels.begin(), levels.end(), level) == levels.end()) levels.push_back(level);
      if (levels.size() > kMaxBandLevels) break;
    }
    if (levels.size() >= 2 && levels.size() <= kMaxBandLevels) out.push_back(name);
  }
  return out;
}

Chart rde_band_chart(const std::vector<SeriesSummary>& series, const std::string& factor,
                     std::optional<double> target_rde) {
  // level (in first-seen order) → Δ* → RDE (%) of every series with one there
  std::vector<std::string> levels;
  std::map<std::string, std::map<double, std::vector<double>>> rde;
  std::map<std::string, int> members;
  for (const auto& s : series) {
    if (!s.extrapolation) continue;
    const std::string level = factor.empty() ? std::string("all series") : level_of(s, factor);
    if (!rde.count(level)) levels.push_back(level);
    auto& by_grid = rde[level];
    bool any = false;
    for (const auto& g : s.extrapolation->grids) {
      if (!g.rde || !std::isfinite(*g.rde)) continue;
      by_grid[grid_key(g.h)].push_back(*g.rde * 100.0);
      any = true;
    }
    members[level] += any ? 1 : 0;
  }
  Chart chart;
  chart.id = "fig2-rde-" + (factor.empty() ? std::string("all") : slugify(factor));
  chart.title = factor.empty() ? "RDE = U/|f_{0}| over all series" : "RDE = U/|f_{0}| by " + factor;
  const CaseVocabulary words = study_vocabulary(series);
  chart.subtitle = "at each " + words.h_symbol +
                   ": the median over the series (solid) and the 10th and 90th percentiles (dashed); "
                   "every series' value in grids.csv";
  chart.x = delta_star_axis(words.h_meaning);
  chart.y = rde_percent_axis();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const auto& by_grid = rde[levels[i]];
    if (by_grid.empty()) continue;
    const int colour = static_cast<int>(i);
    const std::string name = factor.empty() ? levels[i] : factor + " = " + levels[i];
    ChartSeries median{name + " (" + std::to_string(members[levels[i]]) + " series)", {}, {}, {},
                       marker_for(colour), true, false, false, colour};
    ChartSeries low{"", {}, {}, {}, Marker::none, true, true, false, colour};
    ChartSeries high = low;
    for (auto [h, values] : by_grid) {
      std::sort(values.begin(), values.end());
      median.x.push_back(h);
      median.y.push_back(quantile(values, 0.5));
      low.x.push_back(h);
      low.y.push_back(quantile(values, 0.1));
      high.x.push_back(h);
      high.y.push_back(quantile(values, 0.9));
    }
    chart.series.push_back(std::move(median));
    chart.series.push_back(std::move(low));
    chart.series.push_back(std::move(high));
  }
  if (target_rde) chart.hlines.push_back({*target_rde * 100.0, "target RDE " + format_percent(*target_rde), 6, true});
  if (chart.series.empty()) chart.note = "No series has an uncertainty yet (needs 4 converged grids).";
  return chart;
}

}  // namespace gridfree
