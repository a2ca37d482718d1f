// SPDX-License-Identifier: GPL-3.0-or-later
// The sampled-Gaussian symbol (deposition/gaussian_symbol.h) against an
// independent direct sum in space, its normalisation, and the aliasing bound
// on its variance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "deposition/gaussian_symbol.h"

namespace gridfree {
namespace {

// Σ_m g_m cos(mω) / Σ_m g_m over |m| ≤ 400, in long double: for s/Δ ≤ 8 the
// omitted terms are below exp(−400²/128) — nothing.
double direct_symbol(double omega, double s_over_h) {
  long double num = 0, den = 0;
  for (int m = -400; m <= 400; ++m) {
    const long double g = std::exp(-0.5L * m * m / (s_over_h * s_over_h));
    num += g * std::cos(static_cast<long double>(m) * omega);
    den += g;
  }
  return double(num / den);
}

TEST(GaussianSymbol, MatchesTheSampledKernelsDtftInBothSummationBranches) {
  // s/Δ below and above the switch at a = 1/(2π) (s/Δ = 0.564).
  for (double r : {0.1, 0.3, 0.5, 0.56, 0.57, 0.8, 1.0, 2.5, 6.0})
    for (double omega : {0.0, 0.3, 1.0, 2.0, 3.0, std::numbers::pi, 4.0, -1.0}) {
      // Both are sums of O(1) terms normalised to 1: a few ulps each.
      EXPECT_NEAR(sampled_gaussian_symbol(omega, r), direct_symbol(omega, r), 1e-14) << "s/Δ " << r << " ω " << omega;
    }
}

TEST(GaussianSymbol, IsExactlyOneAtZeroFrequencyAndIdentityForZeroWidth) {
  for (double r : {0.05, 0.5, 0.6, 3.0}) EXPECT_EQ(sampled_gaussian_symbol(0.0, r), 1.0);
  EXPECT_EQ(sampled_gaussian_symbol(2.0, 0.0), 1.0);
  const auto f = gaussian_axis_factors(10, 0.1, 0.0, true);
  for (double v : f) EXPECT_EQ(v, 0.1);  // the identity times the round-trip scale 1/n
}

TEST(GaussianSymbol, AxisFactorsSampleTheSymbolAtTheTransformsFrequencies) {
  const int n = 12;
  const double h = 0.2, s = 0.3;
  const auto per = gaussian_axis_factors(n, h, s * s, true);
  const auto wall = gaussian_axis_factors(n, h, s * s, false);
  for (int k = 0; k < n; ++k) {
    EXPECT_NEAR(per[std::size_t(k)] * n, direct_symbol(2 * std::numbers::pi * k / n, s / h), 1e-14);
    EXPECT_NEAR(wall[std::size_t(k)] * 2 * n, direct_symbol(std::numbers::pi * k / n, s / h), 1e-14);
  }
}

TEST(GaussianSymbol, VarianceIsTheTargetUpToTheAliasingBound) {
  // ε = 1 − Var/s² ≤ 8π²(s/Δ)² exp(−2π²s²/Δ²) (docs/TRANSFER.md), and the
  // bound is its leading term: for s ≥ 0.6Δ it is tight to 0.2 %, so the
  // test also fails if the kernel were, e.g., the continuous Gaussian's
  // variance s² (ε = 0).
  for (double r : {0.3, 0.5, 0.6, 0.8, 1.0, 1.5, 3.0}) {
    const double v = sampled_gaussian_variance_h2(r);
    const double eps = 1 - v / (r * r);
    const double bound = 8 * std::numbers::pi * std::numbers::pi * r * r * std::exp(-2 * std::numbers::pi * std::numbers::pi * r * r);
    EXPECT_GE(eps, -1e-15) << r;
    EXPECT_LE(eps, bound + 1e-15) << r;
    if (bound > 1e-12 && r >= 0.6) {
      EXPECT_GT(eps, 0.998 * bound) << r;
    }
  }
}

}  // namespace
}  // namespace gridfree
