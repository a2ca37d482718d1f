// One-factor pairs of series and their relative differences (see differences.h).
#include "report/differences.h"

#include <cmath>

#include "report/text_format.h"

namespace gridfree {

std::optional<double> relative_difference(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b) || a + b == 0) return std::nullopt;
  return 2.0 * std::abs(a - b) / std::abs(a + b);
}

std::optional<double> finest_uncertainty(const SeriesSummary& s) {
  if (!s.extrapolation || s.extrapolation->grids.empty()) return std::nullopt;
  const auto& u = s.extrapolation->grids.front().u;  // grids are h ascending
  if (!u || !std::isfinite(*u)) return std::nullopt;
  return u;
}

std::vector<std::pair<std::string, std::string>> series_factors(const SeriesData& series) {
  return {{"case", series.case_name},
          {"convection", series.convection},
          {"fwhm_dp", format_g(series.fwhm_dp, 10)},
          {"drag", series.drag},
          {"deposition", series.deposition.empty() ? "diffusion" : series.deposition}};
}

std::vector<SeriesDifference> one_factor_differences(const std::vector<SeriesSummary>& series) {
  std::vector<SeriesDifference> out;
  for (std::size_t a = 0; a < series.size(); ++a) {
    const auto fa = series_factors(series[a].series);
    for (std::size_t b = a + 1; b < series.size(); ++b) {
      const auto fb = series_factors(series[b].series);
      int differing = 0;
      std::size_t which = 0;
      for (std::size_t k = 0; k < fa.size(); ++k) {
        if (fa[k].second != fb[k].second) {
          ++differing;
          which = k;
        }
      }
      if (differing != 1) continue;
      SeriesDifference d;
      d.factor = fa[which].first;
      d.value_a = fa[which].second;
      d.value_b = fb[which].second;
      d.a = a;
      d.b = b;
      d.f0_a = series[a].f0();
      d.f0_b = series[b].f0();
      if (d.f0_a && d.f0_b) d.relative = relative_difference(*d.f0_a, *d.f0_b);
      d.verdict_a = series[a].verdict;
      d.verdict_b = series[b].verdict;
      d.u_a = finest_uncertainty(series[a]);
      d.u_b = finest_uncertainty(series[b]);
      if (d.u_a && d.u_b && d.f0_a && d.f0_b) {
        d.u_combined = std::hypot(*d.u_a, *d.u_b);
        d.exceeds_u = std::abs(*d.f0_a - *d.f0_b) > *d.u_combined;
        if (*d.f0_a + *d.f0_b != 0) d.u_relative = 2.0 * *d.u_combined / std::abs(*d.f0_a + *d.f0_b);
      }
      out.push_back(d);
    }
  }
  return out;
}

}  // namespace gridfree
