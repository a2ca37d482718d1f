#include "verify/filter_order.h"

#include <cmath>
#include <numbers>

#include "deposition/filter.h"

namespace gridfree {
namespace {

constexpr double kFwhm = 0.2;
constexpr int kSteps = 4;
const double kK = 2.0 * std::numbers::pi;

double mode_factor(double kappa) {
  const double nu0 = kFwhm * kFwhm / (16.0 * std::log(2.0));
  return std::pow(1.0 + nu0 * kappa * kappa / kSteps, -kSteps);
}

}  // namespace

OrderStudy filter_order(const std::vector<int>& grids) {
  OrderStudy s;
  s.equation = "diffusion_filter";
  s.scheme = "backward_euler_3point";
  s.norm = "max cell value";
  s.expected_order = 2.0;
  for (int n : grids) {
    Grid g;
    g.n = {n, n, 1};
    g.length = {1.0, 1.0, 1.0 / n};
    g.periodic = {true, true, true};
    std::vector<double> alpha(g.cells());
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        alpha[g.index(i, j, 0)] = 1.0 + 0.5 * std::sin(kK * g.centre(0, i)) + std::cos(2 * kK * g.centre(1, j)) / 3.0;
    FilterSettings settings;
    settings.fwhm_cm = kFwhm;
    settings.steps = kSteps;
    settings.tolerance = 1e-14;
    const FilterStats stats = apply_filter(g, settings, alpha);
    s.grids.push_back(n);
    s.h.push_back(1.0 / n);
    if (!stats.converged) {
      s.failure = "filter solve did not converge on " + std::to_string(n) + " cells";
      s.errors.push_back(std::nan(""));
      break;
    }
    double err = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double exact = 1.0 + 0.5 * std::sin(kK * g.centre(0, i)) * mode_factor(kK) +
                             std::cos(2 * kK * g.centre(1, j)) / 3.0 * mode_factor(2 * kK);
        err = std::max(err, std::abs(alpha[g.index(i, j, 0)] - exact));
      }
    s.errors.push_back(err);
  }
  s.observed_order = observed_order(s.h, s.errors);
  return s;
}

}  // namespace gridfree
