// SPDX-License-Identifier: GPL-3.0-or-later
// Three-grid GCI bands and φ_ext beside the regression (see chart_gci.h).
//
// The GCI band of a triplet is C08's error band on its fine-grid value:
// φ1 ± GCI_fine·|φ1| (GCI_fine relative, extrap/gci.h). The bands are drawn
// 2 % right of h1 so they do not hide the regression's ±U at the same grid.
#include "report/chart_gci.h"

#include <algorithm>
#include <cmath>

#include "report/chart_common.h"
#include "report/series_vocabulary.h"

namespace gridfree {

namespace {

constexpr double kDodge = 1.02;  // bands at 1.02·h1, beside the grid's own ±U

struct ConvergenceStyle {
  const char* type;
  const char* legend;
  Marker marker;
  int colour;
};

constexpr ConvergenceStyle kStyles[] = {
    {"monotone", "GCI band, monotone triplet", Marker::circle, 2},
    {"oscillatory", "GCI band, oscillatory triplet", Marker::triangle, 4},
    {"divergent", "GCI band, divergent triplet", Marker::x_mark, 1},
};

}  // namespace

Chart gci_chart(const SeriesSummary& s, std::size_t index) {
  Chart chart;
  chart.id = "gci-" + series_slug(s, index);
  chart.title = "Three-grid GCI vs regression: " + s.label + title_suffix(s);
  // The case's words: an external series' quantity and declared h (docs/EXTERNAL.md).
  const CaseVocabulary words = series_vocabulary(s.series);
  chart.subtitle = "each consecutive triplet at its finest " + words.h_symbol +
                   ": φ_{1} ± GCI_{fine} (marker = convergence type) and φ_{ext}";
  chart.x = delta_star_axis(words.compact_h_axis + " (finest grid of the triplet)");
  chart.y = {words.compact_value_axis, AxisScale::linear, std::nullopt, std::nullopt};
  if (!s.extrapolation || s.extrapolation->gci.empty()) return chart;
  const ExtrapolationView& e = *s.extrapolation;
  ChartSeries grids{"f_{i} ± U_{i} (regression)", {}, {}, {}, Marker::circle, false, false, true, 0};
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
  std::vector<ChartSeries> bands;
  for (const auto& style : kStyles)
    bands.push_back({style.legend, {}, {}, {}, style.marker, false, false, false, style.colour});
  int without_band = 0;
  ChartSeries ext{"φ_{ext} (three-grid Richardson)", {}, {}, {}, Marker::diamond, false, false, false, 1};
  for (const auto& t : e.gci) {
    ext.x.push_back(t.h[0]);
    ext.y.push_back(t.f_ext ? *t.f_ext : NAN);
    const ExtrapolatedGrid* fine = e.grid_at(t.h[0]);
    const auto style = std::find_if(std::begin(kStyles), std::end(kStyles),
                                    [&](const ConvergenceStyle& st) { return t.convergence == st.type; });
    if (!fine || style == std::end(kStyles)) {
      ++without_band;
      continue;
    }
    ChartSeries& band = bands[static_cast<std::size_t>(style - std::begin(kStyles))];
    band.x.push_back(t.h[0] * kDodge);
    band.y.push_back(fine->f);
    band.y_error.push_back(t.gci_fine ? *t.gci_fine * std::abs(fine->f) : NAN);
  }
  // The y range follows the regression data; φ_ext values far outside it
  // (the scatter this chart is about) become arrows on the edge.
  if (std::isfinite(lo) && std::isfinite(hi)) {
    const double span = std::max(hi - lo, 1e-6 * std::max(std::abs(hi), 1.0));
    double ext_lo = lo, ext_hi = hi;
    auto widen = [&](double y) {
      if (std::isfinite(y) && y >= lo - 2 * span && y <= hi + 2 * span) {
        ext_lo = std::min(ext_lo, y);
        ext_hi = std::max(ext_hi, y);
      }
    };
    for (double y : ext.y) widen(y);
    for (const auto& b : bands) {
      for (std::size_t i = 0; i < b.y.size(); ++i) {
        if (std::isfinite(b.y_error[i])) {
          widen(b.y[i] - b.y_error[i]);
          widen(b.y[i] + b.y_error[i]);
        }
      }
    }
    const AxisTicks t = linear_ticks(ext_lo - 0.05 * span, ext_hi + 0.05 * span, 6);
    chart.y.min = t.lo;
    chart.y.max = t.hi;
  }
  // Room right of the coarsest grid, so its error bar is not on the frame.
  if (!e.grids.empty() && chart.x.scale == AxisScale::linear)
    chart.x.max = linear_ticks(0.0, e.grids.back().h * 1.05, 7).hi;
  chart.series.push_back(grids);
  for (auto& b : bands) {
    if (!b.x.empty()) chart.series.push_back(std::move(b));
  }
  chart.series.push_back(ext);
  if (auto f0 = s.f0()) chart.hlines.push_back({*f0, "f_{0} (regression)", 6, true});
  chart.note = "GCI bands drawn 2 % right of their grid.";
  if (without_band > 0)
    chart.note += " " + std::to_string(without_band) + " triplet(s) without a GCI (zero difference or no order).";
  return chart;
}

}  // namespace gridfree
