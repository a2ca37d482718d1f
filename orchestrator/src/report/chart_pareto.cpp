// SPDX-License-Identifier: GPL-3.0-or-later
// Pareto front of cost against a-priori RDE (see chart_pareto.h).
#include "report/chart_pareto.h"

#include <algorithm>
#include <set>
#include <cmath>
#include <numeric>

#include "report/chart_common.h"
#include "extrap/value_format.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

std::vector<std::size_t> pareto_front(const std::vector<CostPoint>& points) {
  auto finite = [](const CostPoint& p) { return std::isfinite(p.rde) && std::isfinite(p.cost); };
  auto dominates = [](const CostPoint& q, const CostPoint& p) {
    return q.rde <= p.rde && q.cost <= p.cost && (q.rde < p.rde || q.cost < p.cost);
  };
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) continue;
    const bool dominated = std::any_of(points.begin(), points.end(), [&](const CostPoint& q) {
      return finite(q) && dominates(q, points[i]);
    });
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    return points[a].rde != points[b].rde ? points[a].rde < points[b].rde : points[a].cost < points[b].cost;
  });
  return front;
}

double grid_cost(const GridPoint& g, CostMeasure measure) {
  if (measure == CostMeasure::cpu_seconds) return g.cpu_s;
  const double cells = static_cast<double>(g.nx) * g.ny * g.nz;
  return measure == CostMeasure::cells ? cells : cells * g.iterations;
}

Chart speed_accuracy_chart(const std::vector<SeriesSummary>& series, CostMeasure measure) {
  const bool cpu = measure == CostMeasure::cpu_seconds;
  Chart chart;
  chart.id = cpu ? "speed-accuracy" : "speed-accuracy-work";
  const CaseVocabulary words = study_vocabulary(series);
  const std::string work = measure == CostMeasure::cells ? "cells" : "cells × " + words.iteration + "s";
  chart.title = "What a target costs: " + (cpu ? std::string("CPU time") : work) + " against RDE";
  chart.subtitle = "each converged grid at its a-priori RDE = U_{i}/|f_{0}|; the Pareto front of each converged "
                   "series connected, dominated grids faded; series not converged hollow and never on a front";
  chart.x = {"RDE (a priori, %)", AxisScale::linear, 0.0, std::nullopt};
  chart.x.auto_log = true;
  chart.x.tick_suffix = "%";
  chart.y = {cpu ? "CPU time (s, this machine)" : work, AxisScale::linear, 0.0, std::nullopt};
  chart.y.auto_log = true;
  std::vector<ChartSeries> unconverged;
  std::set<std::string> labelled;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& s = series[i];
    if (!s.extrapolation || !s.f0()) continue;
    std::vector<CostPoint> points;
    std::vector<double> h;
    for (const GridPoint& g : s.series.grids) {
      const ExtrapolatedGrid* e = s.extrapolated(g);
      if (!e || !e->rde) continue;
      points.push_back({*e->rde * 100.0, grid_cost(g, measure)});
      h.push_back(g.delta_star);
    }
    const std::string legend = s.label + title_suffix(s) + " (" + (s.verdict.empty() ? "no verdict" : s.verdict) + ")";
    if (s.verdict != "converged") {
      // Its RDEs come from an extrapolation that may still move: drawn
      // hollow and dashed, never as a front to pick a grid from.
      ChartSeries other{legend, {}, {}, {}, marker_for(int(i)), true, true, true, int(i)};
      for (std::size_t k = 0; k < points.size(); ++k) {
        if (!std::isfinite(points[k].rde) || !std::isfinite(points[k].cost)) continue;
        other.x.push_back(points[k].rde);
        other.y.push_back(points[k].cost);
      }
      if (!other.x.empty()) unconverged.push_back(std::move(other));
      continue;
    }
    const auto front = pareto_front(points);
    ChartSeries on{legend, {}, {}, {}, marker_for(int(i)), true, false, false, int(i)};
    ChartSeries off{"", {}, {}, {}, marker_for(int(i)), false, false, false, int(i)};
    off.faded = true;
    for (std::size_t k : front) {
      on.x.push_back(points[k].rde);
      on.y.push_back(points[k].cost);
      // Each cell size labelled once, at the first front that holds it:
      // several series' fronts share the grids, and a label per point would
      // crowd the chart.
      const std::string label = cell_size_text(series_vocabulary(s.series), h[k]);
      on.point_labels.push_back(labelled.insert(label).second ? label : std::string());
    }
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (std::find(front.begin(), front.end(), k) != front.end()) continue;
      off.x.push_back(points[k].rde);
      off.y.push_back(points[k].cost);
    }
    if (!on.x.empty()) chart.series.push_back(on);
    if (!off.x.empty()) chart.series.push_back(off);
  }
  if (chart.series.empty()) {
    // Nothing converged to recommend: the chart is not written (report_charts.cpp).
    chart.note = "No converged series: no grid can be recommended.";
  } else {
    for (auto& u : unconverged) chart.series.push_back(std::move(u));
    chart.series.push_back({"faded: dominated grid", {}, {}, {},
                            Marker::circle, false, false, false, 7});
    chart.series.back().faded = true;
    chart.note = "For a target RDE, the cheapest grid is the lowest front point left of it whose finer grids are "
                 "all left of it too (table \"What a target costs\")." +
                 std::string(chart.series.size() > 3 ? " Each grid size is labelled once, on the first front that has it."
                                                     : "");
  }
  return chart;
}

}  // namespace gridfree
