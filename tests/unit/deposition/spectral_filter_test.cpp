// SPDX-License-Identifier: GPL-3.0-or-later
// The exact pseudo-time filter (deposition/spectral_filter.h): a single
// eigenmode decays by exactly exp(ν λ_k); Σ α is conserved to round-off; the
// operator is symmetric; and backward Euler with N steps converges to it at
// the expected first order, error ∝ 1/N.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "deposition/filter.h"
#include "deposition/spectral_filter.h"

namespace gridfree {
namespace {

Grid box(std::array<int, 3> n, std::array<bool, 3> periodic) {
  Grid g;
  g.n = n;
  g.length = {n[0] * 0.1, n[1] * 0.05, n[2] * 0.1};
  g.periodic = periodic;
  return g;
}

std::vector<double> uniform_random_field(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> f(n);
  for (double& v : f) v = u(rng);
  return f;
}

TEST(SpectralFilter, EigenmodesDecayByExpNuLambda) {
  const int n = 16;
  const double h = 0.1, nu = 0.013;
  for (bool periodic : {false, true}) {
    const Grid g = box({n, 1, 1}, {periodic, false, false});
    SpectralFilter f(g, {nu, 0, 0});
    const int k = 3;
    std::vector<double> mode(n);
    for (int i = 0; i < n; ++i)
      mode[std::size_t(i)] = periodic ? std::cos(2 * std::numbers::pi * k * (i + 0.5) / n)
                                      : std::cos(std::numbers::pi * k * (i + 0.5) / n);
    std::vector<double> out = mode;
    f.apply(out);
    const double s = periodic ? std::sin(std::numbers::pi * k / n) : std::sin(std::numbers::pi * k / (2.0 * n));
    const double decay = std::exp(-nu * 4 / (h * h) * s * s);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(out[std::size_t(i)], decay * mode[std::size_t(i)], 1e-14);
  }
}

TEST(SpectralFilter, ConservesAndIsSymmetric) {
  const Grid g = box({12, 20, 6}, {true, false, true});
  SpectralFilter f(g, {0.02, 0.01, 0.03});
  std::vector<double> a = uniform_random_field(g.cells(), 1), b = uniform_random_field(g.cells(), 2);
  long double sa = 0, sfa = 0;
  for (double v : a) sa += v;
  const std::vector<double> a0 = a, b0 = b;
  f.apply(a);
  f.apply(b);
  for (double v : a) sfa += v;
  EXPECT_NEAR(double(sfa), double(sa), 1e-14 * double(sa));  // round-off of two transforms
  long double ab = 0, ba = 0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    ab += a[c] * b0[c];
    ba += a0[c] * b[c];
  }
  EXPECT_NEAR(double(ab), double(ba), 1e-13 * double(ab));
}

TEST(SpectralFilter, BackwardEulerStepsConvergeToItAtFirstOrder) {
  const Grid g = box({24, 16, 1}, {true, false, false});
  FilterSettings s;
  s.fwhm_cm = 0.5;
  s.tolerance = 1e-14;
  std::vector<double> init(g.cells(), 0.0);
  init[g.index(5, 3, 0)] = 1.0;  // a point source: the sharpest test of the kernel shape
  s.integration = FilterIntegration::kExact;
  std::vector<double> exact = init;
  apply_filter(g, s, exact);
  s.integration = FilterIntegration::kSteps;
  std::vector<double> errors;
  for (int steps : {16, 32, 64}) {
    s.steps = steps;
    std::vector<double> be = init;
    apply_filter(g, s, be);
    double e = 0;
    for (std::size_t c = 0; c < g.cells(); ++c) e = std::max(e, std::abs(be[c] - exact[c]));
    errors.push_back(e);
  }
  // Backward Euler is first order in Δτ = 1/N: halving Δτ halves the error
  // (ratio 2 + O(1/N); 1.8–2.2 allows the O(1/N) term at N = 16).
  EXPECT_NEAR(errors[0] / errors[1], 2.0, 0.2);
  EXPECT_NEAR(errors[1] / errors[2], 2.0, 0.2);
}

TEST(FilterDiffusivity, ConsistentSubtractsTheKernelVariance) {
  Grid g = box({10, 10, 10}, {true, false, true});
  FilterSettings s;
  s.fwhm_cm = 0.6;
  s.diffusivity = FilterDiffusivity::kConsistent;
  s.kernel_variance_per_h2 = 1.0 / 6;
  const auto nu = filter_diffusivity(g, s);
  const double sigma2 = 0.36 / (8 * std::numbers::ln2);
  EXPECT_NEAR(2 * nu[0], sigma2 - 0.01 / 6, 1e-15);
  EXPECT_NEAR(2 * nu[1], sigma2 - 0.0025 / 6, 1e-15);
}

}  // namespace
}  // namespace gridfree
