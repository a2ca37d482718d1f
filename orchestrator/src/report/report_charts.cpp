// Builds the report charts from the series summaries (see report_charts.h).
#include "report/report_charts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/text_format.h"

namespace gridfree {

namespace {

std::string series_slug(const SeriesSummary& s, std::size_t index) {
  char prefix[16];
  std::snprintf(prefix, sizeof prefix, "%02zu_", index + 1);
  return prefix + slugify(s.label);
}

std::string title_suffix(const SeriesSummary& s) { return s.incomplete ? " (incomplete)" : ""; }

// A fit curve sampled on [h_from, h_to]; empty when a coefficient is missing.
template <typename F>
ChartSeries curve(std::string name, double h_from, double h_to, F&& f, int colour) {
  ChartSeries c;
  c.name = std::move(name);
  c.marker = Marker::none;
  c.dashed = true;
  c.colour = colour;
  const int n = 120;
  for (int i = 0; i <= n; ++i) {
    const double h = h_from + (h_to - h_from) * i / n;
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
  std::string out = "method " + (e.method.empty() ? std::string("?") : e.method) + ", f0 = " + format_g(s.f0(), 8);
  if (e.p) out += ", p = " + format_g(*e.p, 3);
  if (auto q = e.fit_quality()) out += ", σ_RE/R_f = " + format_g(*q, 2) + (*q < 1 ? " (good fit)" : " (poor fit)");
  if (s.insufficient()) out += "; insufficient grids: no uncertainty";
  return out;
}

}  // namespace

Chart series_chart(const SeriesSummary& s, std::size_t index) {
  Chart chart;
  chart.id = "fig1-" + series_slug(s, index);
  chart.title = "DP* vs Δ*: " + s.label + title_suffix(s);
  chart.subtitle = fit_subtitle(s);
  chart.x = {"Δ* (cell size / particle diameter)", AxisScale::linear, 0.0, std::nullopt};
  chart.y = {"DP* = Δp / (ρ_g U0²)", AxisScale::linear, std::nullopt, std::nullopt};
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
  for (double h : s.h) points.point_labels.push_back(format_g(h, 3));  // Δ* of each point
  chart.series.push_back(points);
  if (e && !s.h.empty()) {
    const double h_max = s.h.back() * 1.05;
    // The chosen fit solid colour, the other faded and labelled "rejected".
    auto tag = [&](const char* method) { return e->method == method ? " (chosen)" : " (rejected)"; };
    const auto& pw = e->power;
    if (pw.f0 && pw.c && pw.p) {
      const double from = *pw.p > 0 ? 0.0 : s.h.front();
      chart.series.push_back(curve(std::string("power law f₀ + c hᵖ") + tag("power"), from, h_max,
                                   [&](double h) { return *pw.f0 + *pw.c * std::pow(h, *pw.p); }, 2));
      chart.series.back().faded = e->method != "power";
    }
    const auto& mx = e->mixed;
    if (mx.f0 && mx.c1 && mx.c2) {
      chart.series.push_back(curve(std::string("mixed f₀ + c₁h + c₂h²") + tag("mixed"), 0.0, h_max,
                                   [&](double h) { return *mx.f0 + *mx.c1 * h + *mx.c2 * h * h; }, 4));
      chart.series.back().faded = e->method != "mixed";
    }
  }
  add_unusable_points(chart, s);
  if (auto f0 = s.f0()) {
    const std::optional<double> u = e && !e->grids.empty() ? e->grids.front().u : std::nullopt;
    chart.hlines.push_back({*f0, "f₀ = " + format_with_uncertainty(*f0, u, 8), 6, true});
  }
  if (s.series.grids.empty()) chart.note = "No grids in this series.";
  return chart;
}

Chart rde_chart(const std::vector<SeriesSummary>& series) {
  Chart chart;
  chart.id = "fig2-rde";
  chart.title = "Relative discretization error bound RDE = U/|f0|";
  chart.subtitle = "series with at least 4 converged grids";
  chart.x = {"Δ* (cell size / particle diameter)", AxisScale::linear, 0.0, std::nullopt};
  chart.y = {"RDE (%)", AxisScale::linear, 0.0, std::nullopt};
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& s = series[i];
    if (!s.extrapolation) continue;
    ChartSeries c{s.label + title_suffix(s), {}, {}, {}, marker_for(int(i)), true, false, false, int(i)};
    for (const auto& g : s.extrapolation->grids) {
      if (!g.rde) continue;
      c.x.push_back(g.h);
      c.y.push_back(*g.rde * 100.0);
    }
    if (!c.x.empty()) chart.series.push_back(c);
  }
  if (chart.series.empty()) chart.note = "No series has an uncertainty yet (needs 4 converged grids).";
  return chart;
}

Chart speed_accuracy_chart(const std::vector<SeriesSummary>& series) {
  Chart chart;
  chart.id = "speed-accuracy";
  chart.title = "Speed vs accuracy: CPU time of each job against its error";
  chart.subtitle = "error = |DP* − f0| / |f0|, f0 = the series' extrapolated value";
  chart.x = {"error |DP* − f0| / |f0|", AxisScale::log, std::nullopt, std::nullopt};
  chart.y = {"CPU time (s)", AxisScale::log, std::nullopt, std::nullopt};
  for (std::size_t i = 0; i < series.size(); ++i) {
    const auto& s = series[i];
    if (!s.f0()) continue;
    std::vector<std::pair<double, double>> pts;  // (cpu, error)
    for (const GridPoint& g : s.series.grids) {
      if (!is_converged(g)) continue;
      pts.emplace_back(g.cpu_s, s.relative_error(*g.dp_star).value_or(NAN));
    }
    std::sort(pts.begin(), pts.end());
    ChartSeries c{s.label + title_suffix(s), {}, {}, {}, marker_for(int(i)), true, false, false, int(i)};
    for (const auto& [cpu, err] : pts) {
      c.x.push_back(err);
      c.y.push_back(cpu);
    }
    if (!c.x.empty()) chart.series.push_back(c);
  }
  chart.note = chart.series.empty() ? "No series has an extrapolated value yet."
                                    : "Zero error or zero CPU time cannot sit on a log axis: such jobs are arrows on the edge.";
  return chart;
}

Chart gci_chart(const SeriesSummary& s, std::size_t index) {
  Chart chart;
  chart.id = "gci-" + series_slug(s, index);
  chart.title = "Three-grid GCI vs regression: " + s.label + title_suffix(s);
  chart.subtitle = "φ_ext of each consecutive triplet (at its finest Δ*) beside f_i ± U_i and f0";
  chart.x = {"Δ* (finest grid of the triplet)", AxisScale::linear, 0.0, std::nullopt};
  chart.y = {"DP*", AxisScale::linear, std::nullopt, std::nullopt};
  if (!s.extrapolation || s.extrapolation->gci.empty()) return chart;
  const ExtrapolationView& e = *s.extrapolation;
  ChartSeries grids{"f_i ± U_i (regression)", {}, {}, {}, Marker::circle, false, false, true, 0};
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& g : e.grids) {
    const double u = g.u.value_or(0.0);
    grids.x.push_back(g.h);
    grids.y.push_back(g.f);
    grids.y_error.push_back(g.u ? *g.u : NAN);
    lo = std::min(lo, g.f - u);
    hi = std::max(hi, g.f + u);
  }
  if (auto f0 = s.f0()) {
    lo = std::min(lo, *f0);
    hi = std::max(hi, *f0);
  }
  ChartSeries ext{"φ_ext (three-grid Richardson)", {}, {}, {}, Marker::diamond, false, false, false, 1};
  for (const auto& t : e.gci) {
    ext.x.push_back(t.h[0]);
    ext.y.push_back(t.f_ext ? *t.f_ext : NAN);
  }
  // The y range follows the regression data; φ_ext values far outside it
  // (the scatter this chart is about) become arrows on the edge.
  if (std::isfinite(lo) && std::isfinite(hi)) {
    const double span = std::max(hi - lo, 1e-6 * std::max(std::abs(hi), 1.0));
    double ext_lo = lo, ext_hi = hi;
    for (double y : ext.y) {
      if (std::isfinite(y) && y >= lo - 2 * span && y <= hi + 2 * span) {
        ext_lo = std::min(ext_lo, y);
        ext_hi = std::max(ext_hi, y);
      }
    }
    const AxisTicks t = linear_ticks(ext_lo - 0.05 * span, ext_hi + 0.05 * span, 6);
    chart.y.min = t.lo;
    chart.y.max = t.hi;
  }
  chart.series.push_back(grids);
  chart.series.push_back(ext);
  if (auto f0 = s.f0()) chart.hlines.push_back({*f0, "f0 (regression)", 6, true});
  return chart;
}

std::vector<NamedChart> report_charts(const std::vector<SeriesSummary>& series) {
  std::vector<NamedChart> out;
  out.push_back({"fig2_rde.svg", "RDE of every grid of every series (docs/PHYSICS.md §8): lower is better; FM18 found < 4% everywhere.",
                 rde_chart(series), {}});
  out.push_back({"speed_accuracy.svg",
                 "CPU time against error for every converged job: the cheapest grid that meets a target error is the leftmost-lowest point under it.",
                 speed_accuracy_chart(series), {}});
  for (std::size_t i = 0; i < series.size(); ++i) {
    const std::string slug = series_slug(series[i], i);
    out.push_back({"fig1_" + slug + ".svg",
                   "DP* against Δ* for " + series[i].label + ", with the fits, f0 and U.",
                   series_chart(series[i], i), {}});
    if (series[i].extrapolation && !series[i].extrapolation->gci.empty()) {
      out.push_back({"gci_" + slug + ".svg",
                     "Classic three-grid extrapolation of every consecutive triplet for " + series[i].label +
                         ", beside the regression.",
                     gci_chart(series[i], i), {}});
    }
  }
  return out;
}

}  // namespace gridfree
