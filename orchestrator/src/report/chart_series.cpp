// SPDX-License-Identifier: GPL-3.0-or-later
// DP* vs Δ* of one series (see chart_series.h).
#include "report/chart_series.h"

#include <algorithm>
#include <cmath>

#include "extrap/verdict.h"

#include "report/chart_common.h"
#include "extrap/value_format.h"
#include "report/series_vocabulary.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

// A fit curve sampled on [h_from, h_to] (geometrically when h_from > 0, so
// it is smooth on a log axis too).
template <typename F>
ChartSeries curve(std::string name, double h_from, double h_to, F&& f, int colour) {
  ChartSeries c;
  c.name = std::move(name);
  c.marker = Marker::none;
  c.dashed = true;
  c.colour = colour;
  const int n = 120;
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    const double h = h_from > 0 ? h_from * std::pow(h_to / h_from, t) : h_from + (h_to - h_from) * t;
    c.x.push_back(h);
    c.y.push_back(f(h));
  }
  return c;
}

// Grids without a usable value, drawn apart from the converged ones.
void add_unusable_points(Chart& chart, const SeriesSummary& s) {
  ChartSeries failed{"failed / not converged", {}, {}, {}, Marker::x_mark, false, false, false, 1};
  ChartSeries pending{"pending (queued/running)", {}, {}, {}, Marker::circle, false, false, true, 7};
  for (const GridPoint& g : s.series.grids) {
    if (is_failed(g)) {
      failed.x.push_back(g.delta_star);
      failed.y.push_back(g.dp_star && std::isfinite(*g.dp_star) ? *g.dp_star : NAN);
    } else if (is_pending(g)) {
      pending.x.push_back(g.delta_star);
      pending.y.push_back(NAN);
    }
  }
  if (!failed.x.empty()) chart.series.push_back(failed);
  if (!pending.x.empty()) chart.series.push_back(pending);
}

std::string fit_subtitle(const SeriesSummary& s) {
  if (!s.extrapolation || !s.f0()) return s.note().empty() ? "no extrapolation" : s.note();
  const ExtrapolationView& e = *s.extrapolation;
  std::string out = "method " + (e.method.empty() ? std::string("?") : e.method) + ", " + f0_label(s);
  if (const std::string f1 = finest_label(s); !f1.empty()) out += ", " + f1;
  // With a mixed fit chosen, p is the rejected power law's (why it was rejected).
  if (e.p) out += (e.method == "power" ? ", p = " : ", power law's p = ") + format_g(*e.p, 3) +
                  (e.method == "power" ? "" : " (rejected)");
  // With fewer than min_dof degrees of freedom the fit cannot be judged.
  const int dof = static_cast<int>(e.grids.size()) - 3;
  if (auto q = e.fit_quality())
    out += ", σ_{RE}/R_{f} = " + format_g(*q, 3) +
           (dof < VerdictRules{}.min_dof ? " (fit cannot be judged: " + std::to_string(std::max(dof, 0)) +
                                               " degree(s) of freedom)"
                                         : (*q < 1 ? " (good fit)" : " (poor fit)"));
  if (s.insufficient()) out += "; insufficient grids: no uncertainty";
  return out;
}

}  // namespace

Chart series_chart(const SeriesSummary& s, std::size_t index) {
  Chart chart;
  chart.id = "fig1-" + series_slug(s, index);
  // An external series names its quantity and the meaning of its h (docs/EXTERNAL.md).
  const CaseVocabulary words = series_vocabulary(s.series);
  chart.title = words.quantity_symbol + " vs " + words.h_symbol + ": " + s.label + title_suffix(s);
  chart.subtitle = fit_subtitle(s);
  chart.x = delta_star_axis(s.series.h_axis());
  chart.y = {s.series.value_axis(), AxisScale::linear, std::nullopt, std::nullopt};
  ChartSeries points{"converged grids", s.h, s.f, {}, Marker::circle, false, false, false, 0};
  const ExtrapolationView* e = s.extrapolation ? &*s.extrapolation : nullptr;
  bool any_u = false;
  if (e) {
    for (double h : s.h) {
      const ExtrapolatedGrid* g = e->grid_at(h);
      points.y_error.push_back(g && g->u ? *g->u : NAN);
      any_u = any_u || (g && g->u);
    }
  }
  if (any_u) points.name += " ± U";
  for (double h : s.h) points.point_labels.push_back(format_cell_size(h));  // Δ* of each point
  chart.series.push_back(points);
  if (e && !s.h.empty()) {
    // Down to h = 0 on a linear axis; on a log axis (grids spanning more
    // than a decade) from half the finest Δ*.
    const bool log_x = scale_for_span(s.h.front(), s.h.back()) == AxisScale::log;
    const double h_max = s.h.back() * 1.05, h_min = log_x ? s.h.front() / 2 : 0.0;
    // The chosen fit solid colour, the other faded and labelled "rejected".
    auto tag = [&](const char* method) { return e->method == method ? " (chosen)" : " (rejected)"; };
    const auto& pw = e->power;
    if (pw.f0 && pw.c && pw.p) {
      const double from = *pw.p > 0 ? h_min : s.h.front();
      chart.series.push_back(curve(std::string("power law f_{0} + c h^{p}") + tag("power"), from, h_max,
                                   [&](double h) { return *pw.f0 + *pw.c * std::pow(h, *pw.p); }, 2));
      chart.series.back().faded = e->method != "power";
    }
    const auto& mx = e->mixed;
    if (mx.f0 && mx.c1 && mx.c2) {
      chart.series.push_back(curve(std::string("mixed f_{0} + c_{1}h + c_{2}h^{2}") + tag("mixed"), h_min, h_max,
                                   [&](double h) { return *mx.f0 + *mx.c1 * h + *mx.c2 * h * h; }, 4));
      chart.series.back().faded = e->method != "mixed";
    }
  }
  add_unusable_points(chart, s);
  if (auto f0 = s.f0()) chart.hlines.push_back({*f0, f0_label(s), 6, true});
  if (s.series.grids.empty()) chart.note = "No grids in this series.";
  return chart;
}

}  // namespace gridfree
