// SPDX-License-Identifier: GPL-3.0-or-later
// Spread of f0 over the admissible fits (see model_average.h).
#include "extrap/model_average.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "extrap/eh14.h"
#include "extrap/fm_uncertainty.h"
#include "extrap/value_format.h"

namespace gridfree {

ModelSpread admissible_fits(const Series& s, const ExtrapolationOptions& opts, const ExtrapolationResult& chosen) {
  ModelSpread spread;
  if (!chosen.f0 || !std::isfinite(*chosen.f0)) return spread;
  spread.fits.push_back(chosen.method.value_or("chosen"));
  spread.f0.push_back(*chosen.f0);
  ExtrapolationResult expansions;
  for (std::size_t i = 0; i < s.size(); ++i) expansions.grids.push_back({s.h[i], s.f[i], {}, {}, {}});
  eh14_extrapolate(s, opts, expansions);
  const double range = data_range(s.f);
  const std::pair<const char*, const std::optional<FitSummary>*> fits[] = {
      {"power", &expansions.power}, {"first", &expansions.first}, {"second", &expansions.second},
      {"mixed", &expansions.mixed}};
  for (const auto& [name, fit] : fits) {
    if (!*fit || !(*fit)->f0 || !(*fit)->sigma || !std::isfinite(*(*fit)->f0)) continue;
    if (std::string(name) == "power" && !(*fit)->p_found.value_or(false)) continue;
    if (!(*(*fit)->sigma < range)) continue;  // does not describe the data
    spread.fits.push_back(name);
    spread.f0.push_back(*(*fit)->f0);
  }
  return spread;
}

void widen_to_hold(const std::vector<double>& values, double factor, ExtrapolationResult& out) {
  if (values.empty() || !out.f0) return;
  const double sigma = out.sigma_re.value_or(0.0);
  for (auto& g : out.grids) {
    if (!g.u) continue;
    double reach = 0;
    for (double v : values) reach = std::max(reach, std::fabs(v - g.f));
    g.u = std::max(*g.u, factor * reach + sigma);
    if (*out.f0 != 0) g.rde = *g.u / std::fabs(*out.f0);
  }
}

void widen_u0_to_hold(const std::vector<double>& values, ExtrapolationResult& out) {
  if (!out.u0 || !out.f0) return;
  double spread = 0;
  for (double v : values) spread = std::max(spread, std::fabs(v - *out.f0));
  out.u0 = *out.u0 + kMinSafetyFactor * spread;
}

void floor_unreliable_to_data_range(const Series& s, ExtrapolationResult& out) {
  if (s.size() < 2 || !out.f0) return;
  const double floor = kUnreliableRangeFactor * data_range(s.f);
  bool raised = false;
  for (auto& g : out.grids) {
    if (!g.u || *g.u >= floor) continue;
    g.u = floor;
    if (*out.f0 != 0) g.rde = *g.u / std::fabs(*out.f0);
    raised = true;
  }
  if (out.u0 && *out.u0 < floor) {
    out.u0 = floor;
    raised = true;
  }
  if (raised)
    out.notes.push_back("verdict unreliable: U is at least 3 times the data range per refinement, 3 x " +
                        format_value_u(data_range(s.f), std::nullopt, 4) + ", since the fits do not describe these data");
}

void averaged_extrapolate(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out) {
  ExtrapolationOptions capped = opts;
  capped.method = ExtrapolationMethod::kCapped;
  fm_extrapolate(s, capped, out);
  const ModelSpread spread = admissible_fits(s, opts, out);
  widen_to_hold(spread.f0, kMinSafetyFactor, out);
  out.model_spread = spread;
}

}  // namespace gridfree
