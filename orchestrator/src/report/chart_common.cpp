// SPDX-License-Identifier: GPL-3.0-or-later
// Shared chart pieces (see chart_common.h).
#include "report/chart_common.h"

#include <cstdio>

#include "extrap/value_format.h"
#include "report/text_format.h"
#include "report/series_vocabulary.h"

namespace gridfree {

std::string series_slug(const SeriesSummary& s, std::size_t index) {
  char prefix[16];
  std::snprintf(prefix, sizeof prefix, "%02zu_", index + 1);
  return prefix + slugify(s.label);
}

std::string title_suffix(const SeriesSummary& s) { return s.incomplete ? " (incomplete)" : ""; }

ChartAxis delta_star_axis(std::string label) {
  ChartAxis axis{std::move(label), AxisScale::linear, 0.0, std::nullopt};
  axis.auto_log = true;
  return axis;
}

ChartAxis rde_percent_axis() {
  ChartAxis axis{"RDE (%)", AxisScale::linear, 0.0, std::nullopt};
  axis.auto_log = true;
  axis.tick_suffix = "%";
  return axis;
}

std::optional<double> finest_u(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty()) return std::nullopt;
  return s.extrapolation->grids.front().u;
}

std::string f0_label(const SeriesSummary& s) {
  const auto f0 = s.f0();
  if (!f0) return {};
  const std::optional<double> u0 = s.extrapolation ? s.extrapolation->u0 : std::nullopt;
  if (!u0) return "f_{0} = " + format_to_uncertainty_digits(*f0, finest_u(s), 6);  // digits U₁ supports
  return "f_{0} = " + format_with_uncertainty(*f0, u0, 6) + " (U_{0})";
}

std::string finest_label(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty()) return {};
  const ExtrapolatedGrid& g = s.extrapolation->grids.front();
  return "f_{1} = " + format_with_uncertainty(g.f, g.u, 6) + (g.u ? "" : " (no U)") + " (finest " + series_vocabulary(s.series).h_symbol + " = " +
         format_cell_size(g.h) + ")";
}

}  // namespace gridfree
