// SPDX-License-Identifier: GPL-3.0-or-later
// One-factor pairs of series and their relative differences (see differences.h).
#include "report/differences.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

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
  if (!series.quantity.empty()) {  // an external series: the case and the study's own factors
    std::vector<std::pair<std::string, std::string>> out = {{"case", series.case_name}};
    for (const auto& [name, level] : series.levels) out.emplace_back(name, level);
    return out;
  }
  return {{"case", series.case_name},
          {"convection", series.convection},
          {"fwhm_dp", format_g(series.fwhm_dp, 10)},
          {"drag", series.drag},
          {"deposition", series.deposition.empty() ? "diffusion" : series.deposition}};
}

namespace {

SeriesDifference difference_of(const std::vector<SeriesSummary>& series, std::size_t a, std::size_t b,
                               const std::pair<std::string, std::string>& level_a, const std::string& level_b) {
  SeriesDifference d;
  d.factor = level_a.first;
  d.value_a = level_a.second;
  d.value_b = level_b;
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
  return d;
}

}  // namespace

// Series that differ in factor k alone share every other level: grouped by
// the levels of the other factors, each group's pairs are the pairs that
// differ in k (levels equal in k too would be the same series twice, which
// a study cannot hold). O(S·F log S) instead of comparing all S² pairs.
std::vector<SeriesDifference> one_factor_differences(const std::vector<SeriesSummary>& series) {
  std::vector<std::vector<std::pair<std::string, std::string>>> factors;
  factors.reserve(series.size());
  for (const auto& s : series) factors.push_back(series_factors(s.series));
  std::vector<SeriesDifference> out;
  const std::size_t nf = factors.empty() ? 0 : factors.front().size();
  for (std::size_t k = 0; k < nf; ++k) {
    std::set<std::string> levels;
    for (const auto& f : factors) levels.insert(f[k].second);
    if (levels.size() > kMaxPairedLevels) continue;
    std::map<std::vector<std::string>, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < series.size(); ++i) {
      if (factors[i].size() != nf) continue;  // another kind of series: no factor in common
      // The quantity is no factor: a series pairs only with one of its own quantity.
      std::vector<std::string> others = {series[i].series.quantity};
      for (std::size_t j = 0; j < nf; ++j)
        if (j != k) others.push_back(factors[i][j].first + "=" + factors[i][j].second);
      groups[std::move(others)].push_back(i);
    }
    for (const auto& [key, members] : groups)
      for (std::size_t x = 0; x < members.size(); ++x)
        for (std::size_t y = x + 1; y < members.size(); ++y) {
          const std::size_t a = members[x], b = members[y];
          if (factors[a][k].second == factors[b][k].second) continue;
          out.push_back(difference_of(series, a, b, factors[a][k], factors[b][k].second));
        }
  }
  // In series order, as the all-pairs scan gave them.
  std::sort(out.begin(), out.end(), [](const SeriesDifference& l, const SeriesDifference& r) {
    return std::tie(l.a, l.b) < std::tie(r.a, r.b);
  });
  return out;
}

}  // namespace gridfree
