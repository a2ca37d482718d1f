// SPDX-License-Identifier: GPL-3.0-or-later
// Fullmer & Musser (2018) procedure, PHYSICS.md §8 (see fm_uncertainty.h).
#include "extrap/fm_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "extrap/mixed_fit.h"
#include "extrap/power_fit.h"

namespace gridfree {

double fm_safety_factor(double sigma_re, double range) {
  return std::max(kMinSafetyFactor, 3.0 * sigma_re / range);
}

double fm_uncertainty(double f0, double f_i, double sigma_re, double fs) {
  return fs * std::fabs(f0 - f_i) + sigma_re;
}

double extrapolated_value_uncertainty(double f0, double f_finest, double sigma_re) {
  return kMinSafetyFactor * std::fabs(f0 - f_finest) + sigma_re;
}

namespace {

// The fit the procedure extrapolates with: its name, f0, σ and f̂.
struct ChosenFit {
  std::string method;
  double f0 = 0, sigma = 0;
  std::vector<double> fhat;
};

}  // namespace

void fm_extrapolate(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out) {
  const auto w = fit_weights(s.h, opts.weights);

  // 1. Both fits.
  const PowerLawFit power = fit_power_law(s, w, opts.search);
  const FixedOrderFit mixed = fit_mixed(s, w);
  out.power = FitSummary{.f0 = power.f0, .p = power.p, .c = power.c, .c1 = {}, .c2 = {},
                         .sigma = power.sigma, .p_found = power.p_found, .weighted = {}};
  out.mixed = FitSummary{.f0 = mixed.f0, .p = {}, .c = {}, .c1 = mixed.coefficients[0],
                         .c2 = mixed.coefficients[1], .sigma = mixed.sigma, .p_found = {},
                         .weighted = {}};

  // 2. Choice of fit.
  const bool use_power = power.p_found && power.p >= opts.p_low && power.p <= opts.p_high;
  const bool use_capped =
      opts.method == ExtrapolationMethod::kCapped && power.p_found && power.p > opts.p_high;
  ChosenFit chosen{"mixed", mixed.f0, mixed.sigma, mixed.fhat};
  if (use_power) chosen = {"power", power.f0, power.sigma, power.fhat};
  if (use_capped) {
    const FixedOrderFit capped = fit_fixed_orders(s, w, {opts.p_high});
    out.capped = FitSummary{.f0 = capped.f0, .p = opts.p_high, .c = capped.coefficients[0], .c1 = {},
                            .c2 = {}, .sigma = capped.sigma, .p_found = {}, .weighted = {}};
    chosen = {"capped_power", capped.f0, capped.sigma, capped.fhat};
  }
  out.method = chosen.method;
  const double f0 = chosen.f0;
  const std::vector<double>& fhat = chosen.fhat;
  if (power.p_found) out.p = power.p;

  // 3-4. Scatter of the chosen fit, data range, safety factor.
  const double sigma = chosen.sigma;
  const double range = data_range(s.f);
  const double fs = fm_safety_factor(sigma, range);
  out.f0 = f0;
  out.sigma_re = sigma;
  out.fs = fs;
  out.sigma_over_range = sigma / range;

  // 5. Uncertainty and relative discretization error of every grid.
  for (std::size_t i = 0; i < s.size(); ++i) {
    auto& g = out.grids[i];
    g.fhat = fhat[i];
    g.u = fm_uncertainty(f0, s.f[i], sigma, fs);
    if (f0 != 0) g.rde = *g.u / std::fabs(f0);
  }

  if (!power.p_found)
    out.notes.push_back("power-law order not found (minimum of the fit on the search boundary): mixed fit used");
  else if (use_capped)
    out.notes.push_back("observed order above the accepted range: extrapolated with the order capped at p_high");
  else if (!use_power)
    out.notes.push_back("observed order outside the accepted range: mixed fit used");
  if (sigma / range >= 1)
    out.notes.push_back("sigma_RE/R_f >= 1: the fit does not describe the data well (scatter exceeds the data range)");
  if (f0 == 0) out.notes.push_back("f0 = 0: relative discretization errors are undefined");
}

}  // namespace gridfree
