// SPDX-License-Identifier: GPL-3.0-or-later
#include "verify/filter_order.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "deposition/filter.h"

namespace gridfree {
namespace {

constexpr double kFwhm = 0.2;
constexpr int kSteps = 4;
const double kModeK = 2.0 * std::numbers::pi;

double mode_factor(double kappa) {
  const double nu0 = kFwhm * kFwhm / (16.0 * std::log(2.0));
  return std::pow(1.0 + nu0 * kappa * kappa / kSteps, -kSteps);
}

}  // namespace

OrderStudy filter_order_study() {
  OrderStudy s;
  s.equation = "diffusion_filter";
  s.scheme = "backward_euler_3point";
  s.norm = "max cell value";
  s.expected_order = 2.0;
  return s;
}

GridOutcome filter_outcome(int n) {
  Grid g;
  g.n = {n, n, 1};
  g.length = {1.0, 1.0, 1.0 / n};
  g.periodic = {true, true, true};
  std::vector<double> alpha(g.cells());
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      alpha[g.index(i, j, 0)] = 1.0 + 0.5 * std::sin(kModeK * g.centre(0, i)) + std::cos(2 * kModeK * g.centre(1, j)) / 3.0;
  FilterSettings settings;
  settings.fwhm_cm = kFwhm;
  settings.steps = kSteps;
  settings.tolerance = 1e-14;
  const FilterStats stats = apply_filter(g, settings, alpha);
  GridOutcome o;
  if (!stats.converged) {
    o.failure = "filter solve did not converge on " + std::to_string(n) + " cells";
    return o;
  }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double exact = 1.0 + 0.5 * std::sin(kModeK * g.centre(0, i)) * mode_factor(kModeK) +
                           std::cos(2 * kModeK * g.centre(1, j)) / 3.0 * mode_factor(2 * kModeK);
      o.error = std::max(o.error, std::abs(alpha[g.index(i, j, 0)] - exact));
    }
  return o;
}

OrderStudy filter_order(const std::vector<int>& grids) {
  OrderStudy s = filter_order_study();
  std::vector<GridOutcome> outcomes;
  for (int n : grids) {
    outcomes.push_back(filter_outcome(n));
    if (!outcomes.back().failure.empty()) break;
  }
  finish_study(s, grids, outcomes);
  return s;
}

}  // namespace gridfree
