// Shared chart pieces (see chart_common.h).
#include "report/chart_common.h"

#include <cstdio>

#include "report/text_format.h"

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

std::optional<double> finest_u(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty()) return std::nullopt;
  return s.extrapolation->grids.front().u;
}

std::string f0_label(const SeriesSummary& s) {
  const auto f0 = s.f0();
  return f0 ? "f_{0} = " + format_with_uncertainty(*f0, finest_u(s), 6) : std::string();
}

}  // namespace gridfree
