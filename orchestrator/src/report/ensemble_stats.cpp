// SPDX-License-Identifier: GPL-3.0-or-later
// Ensemble statistics (see ensemble_stats.h).
#include "report/ensemble_stats.h"

#include <algorithm>
#include <cmath>

#include "report/differences.h"
#include "report/series_vocabulary.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

// Δ* of the instances match when equal to this relative tolerance (same
// domain, same cells: the values are computed identically).
constexpr double kSameDeltaStar = 1e-9;

bool same_h(double a, double b) { return std::abs(a - b) <= kSameDeltaStar * std::max(std::abs(a), std::abs(b)); }

std::string ensemble_of_case(const std::map<std::string, std::vector<std::string>>& ensembles,
                             const std::string& c) {
  for (const auto& [name, cases] : ensembles)
    if (std::find(cases.begin(), cases.end(), c) != cases.end()) return name;
  return "";
}

}  // namespace

std::optional<double> SampleStats::relative_sd() const {
  if (!sd || mean == 0) return std::nullopt;
  return *sd / std::abs(mean);
}

std::optional<SampleStats> sample_stats(const std::vector<double>& values) {
  std::vector<double> x;
  for (double v : values)
    if (std::isfinite(v)) x.push_back(v);
  if (x.empty()) return std::nullopt;
  SampleStats s;
  s.n = static_cast<int>(x.size());
  double sum = 0;
  for (double v : x) sum += v;
  s.mean = sum / s.n;
  s.min = *std::min_element(x.begin(), x.end());
  s.max = *std::max_element(x.begin(), x.end());
  if (s.n >= 2) {
    double ss = 0;  // two passes: no cancellation between Σx² and n x̄²
    for (double v : x) ss += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(ss / (s.n - 1));
    s.sem = *s.sd / std::sqrt(static_cast<double>(s.n));
  }
  return s;
}

std::string EnsembleConfig::label() const {
  if (external()) {
    std::string out = ensemble + ":";
    for (const auto& [name, level] : levels) out += " " + name + "=" + level;
    return out + " " + quantity;
  }
  std::string out = ensemble + ": " + convection + " fwhm" + format_g(fwhm_dp, 10) + " " + drag;
  if (!deposition.empty() && deposition != "diffusion") out += " " + deposition;
  return out;
}

std::vector<EnsembleConfig> ensemble_configs(const std::vector<SeriesSummary>& series,
                                             const std::map<std::string, std::vector<std::string>>& ensembles) {
  std::vector<EnsembleConfig> out;
  for (const auto& [name, cases] : ensembles) {
    for (std::size_t i = 0; i < series.size(); ++i) {
      const SeriesData& sd = series[i].series;
      if (ensemble_of_case(ensembles, sd.case_name) != name) continue;
      const std::string dep = sd.deposition.empty() ? "diffusion" : sd.deposition;
      auto it = std::find_if(out.begin(), out.end(), [&](const EnsembleConfig& c) {
        return c.ensemble == name && c.convection == sd.convection && c.fwhm_dp == sd.fwhm_dp &&
               c.drag == sd.drag && c.deposition == dep && c.quantity == sd.quantity && c.levels == sd.levels;
      });
      if (it == out.end()) {
        EnsembleConfig c;
        c.ensemble = name;
        c.convection = sd.convection;
        c.fwhm_dp = sd.fwhm_dp;
        c.drag = sd.drag;
        c.deposition = dep;
        c.quantity = sd.quantity;
        c.levels = sd.levels;
        c.factors = series_factors(sd);
        c.factors.erase(c.factors.begin());  // the case: the instances differ in it
        c.vocabulary = series_vocabulary(sd);
        out.push_back(c);
        it = out.end() - 1;
      }
      it->members.push_back(i);
      it->instances.push_back(sd.case_name);
      if (series[i].verdict == "converged") ++it->converged;
    }
  }
  for (auto& c : out) {
    std::vector<double> f0;
    for (std::size_t m : c.members) {
      const auto& s = series[m];
      if (auto v = s.f0(); v && std::isfinite(*v))
        f0.push_back(*v);
      else
        c.without_f0.push_back(s.series.case_name);
      if (!s.extrapolation) continue;
      for (const auto& g : s.extrapolation->grids) {
        auto at = std::find_if(c.grids.begin(), c.grids.end(), [&](const EnsembleGrid& e) { return same_h(e.delta_star, g.h); });
        if (at == c.grids.end()) {
          c.grids.push_back({g.h, {}, {}, std::nullopt, std::nullopt});
          at = c.grids.end() - 1;
        }
        if (g.u && std::isfinite(*g.u)) at->u.push_back(*g.u);
        if (g.rde && std::isfinite(*g.rde)) at->rde.push_back(*g.rde);
      }
    }
    c.f0 = sample_stats(f0);
    std::sort(c.grids.begin(), c.grids.end(),
              [](const EnsembleGrid& a, const EnsembleGrid& b) { return a.delta_star < b.delta_star; });
    for (auto& g : c.grids) {
      g.u_stats = sample_stats(g.u);
      g.rde_stats = sample_stats(g.rde);
    }
  }
  return out;
}

}  // namespace gridfree
