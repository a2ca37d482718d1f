// SPDX-License-Identifier: GPL-3.0-or-later
// The whole deposition kernel (pre-deposition + filter) against its target
// (docs/TRANSFER.md): σ² = δ_f²/(8 ln 2) per axis.
//
// One particle is deposited at M evenly spaced sub-cell positions
// x = (m + ½)Δ/M along a periodic line long enough that the kernel never
// wraps, filtered, and the second and fourth central moments about x are
// measured and averaged over the positions (the centroid and trilinear
// kernels depend on the sub-cell position; their variance Δ²/12 and Δ²/6 is
// the uniform average, which the midpoint rule reproduces up to ∓Δ²/(12M²),
// accounted for exactly).
//
// Variance: "consistent" gives 2ν + cΔ² = σ² exactly (the semi-discrete and
// backward-Euler filters add exactly 2ν, filter_gaussian_test.cpp).
// Fourth cumulant: the position-averaged pre-deposition kernel is the box
// of width Δ (κ4 = −Δ⁴/120) or the tent of half-width Δ (−Δ⁴/60); the exact
// filter is a continuous-time random walk with steps ±Δ, κ4 = 2νΔ² (the
// K → ∞ limit of 2νΔ² + 12ν²/K for K backward-Euler steps). Cumulants add,
// so the excess kurtosis is (κ4_kernel + 2νΔ²)/σ⁴ — O(Δ²/σ²), and not
// below 0.05 unless Δ ≲ σ/4.5: no 3-point operator makes a Gaussian at
// Δ ≈ σ. Eight steps add 12ν²/8, i.e. → 3/8 = 0.375 as Δ → 0.
//
// Gaussian integration: the filter is the sampled Gaussian of variance
// s² = 2ν, whose variance is s²(1 − ε), ε the aliasing term of
// deposition/gaussian_symbol.h (computed here by its direct sum in space),
// and whose fourth cumulant is as small as ε: the excess kurtosis is the
// pre-deposition's alone, −(Δ⁴/120 or Δ⁴/60)/σ⁴, |·| ≤ 1/60 at Δ ≤ σ.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "deposition/filter.h"
#include "deposition/gaussian_symbol.h"
#include "deposition/transfer_stencils.h"

namespace gridfree {
namespace {

struct KernelMoments {
  double variance = 0, excess_kurtosis = 0;
};

KernelMoments measure(PreDeposition kind, double h, double fwhm, FilterIntegration integration, int steps) {
  const double sigma = fwhm / std::sqrt(8 * std::numbers::ln2);
  const int n = 2 * static_cast<int>(std::ceil(12 * sigma / h)) + 8;
  Grid g;
  g.n = {n, 1, 1};
  g.length = {n * h, h, h};
  g.periodic = {true, true, true};
  FilterSettings s;
  s.fwhm_cm = fwhm;
  s.diffusivity = FilterDiffusivity::kConsistent;
  s.kernel_variance_per_h2 = kernel_variance_per_h2(kind);
  s.integration = integration;
  s.steps = steps;
  s.tolerance = 1e-13;
  DiffusionFilter filter(g, s);
  const int positions = 64;
  double m2 = 0, m4 = 0;
  for (int m = 0; m < positions; ++m) {
    const double x = (n / 2 + (m + 0.5) / positions) * h;
    const TransferStencils st(g, {Particle{x, 0.5 * h, 0.5 * h, 0.01}}, {kind, sigma, 4});
    std::vector<double> field;
    st.deposit({1.0}, field);
    filter.apply(field);
    long double s0 = 0, s2 = 0, s4 = 0;
    for (int i = 0; i < n; ++i) {
      const double r = (i + 0.5) * h - x, w = field[std::size_t(i)];
      s0 += w;
      s2 += w * r * r;
      s4 += w * r * r * r * r;
    }
    m2 += double(s2 / s0) / positions;
    m4 += double(s4 / s0) / positions;
  }
  return {m2, m4 / (m2 * m2) - 3.0};
}

TEST(TransferKernel, ConsistentVarianceIsTheTargetAtEveryCellSize) {
  const double fwhm = 0.06, sigma2 = fwhm * fwhm / (8 * std::numbers::ln2);
  for (PreDeposition kind : {PreDeposition::kCentroid, PreDeposition::kTrilinear})
    for (double ratio : {0.25, 0.5, 1.0, 1.3}) {  // Δ/σ
      const double h = ratio * std::sqrt(sigma2);
      for (FilterIntegration integ : {FilterIntegration::kExact, FilterIntegration::kSteps}) {
        const KernelMoments k = measure(kind, h, fwhm, integ, 8);
        // The midpoint rule over M = 64 positions averages (½ − t)² to
        // 1/12 − 1/(12M²) and t(1 − t) to 1/6 + 1/(12M²): the expected
        // variance is σ² ∓ Δ²/(12M²) exactly; what is left is the filter
        // solve (1e-13) and round-off, far below 1e-9 σ².
        const double midpoint = h * h / (12.0 * 64 * 64) * (kind == PreDeposition::kCentroid ? -1 : 1);
        EXPECT_NEAR(k.variance, sigma2 + midpoint, 1e-9 * sigma2)
            << pre_deposition_name(kind) << " Δ/σ = " << ratio << " exact = " << (integ == FilterIntegration::kExact);
      }
    }
}

TEST(TransferKernel, ExactFilterKurtosisIsTheCumulantPredictionAndSmallForFineCells) {
  const double fwhm = 0.06, sigma2 = fwhm * fwhm / (8 * std::numbers::ln2);
  for (double ratio : {0.2, 0.5, 1.0}) {
    const double h = ratio * std::sqrt(sigma2);
    const double two_nu = sigma2 - h * h / 6;
    const KernelMoments k = measure(PreDeposition::kTrilinear, h, fwhm, FilterIntegration::kExact, 0);
    const double predicted = (two_nu * h * h - std::pow(h, 4) / 60) / (sigma2 * sigma2);
    // Tolerance: the midpoint rule's O(1/M²) on the fourth moment.
    EXPECT_NEAR(k.excess_kurtosis, predicted, 2e-3) << "Δ/σ = " << ratio;
    if (ratio <= 0.2) {
      EXPECT_LE(k.excess_kurtosis, 0.05);
    }
  }
  // Eight backward-Euler steps keep 12ν²/8 of fourth cumulant however fine the cells.
  const double h = 0.2 * std::sqrt(sigma2);
  const KernelMoments steps8 = measure(PreDeposition::kTrilinear, h, fwhm, FilterIntegration::kSteps, 8);
  const double nu = (sigma2 - h * h / 6) / 2;
  EXPECT_NEAR(steps8.excess_kurtosis, (2 * nu * h * h + 12 * nu * nu / 8 - std::pow(h, 4) / 60) / (sigma2 * sigma2),
              2e-3);
  EXPECT_GT(steps8.excess_kurtosis, 0.3);
}

TEST(TransferKernel, SemiDiscreteKurtosisFollowsTheDeltaSquaredLawForBothKernels) {
  // Excess kurtosis (2νΔ² + κ4,kernel)/σ⁴ = Δ²/σ² − (c + 1/120 or 1/60)Δ⁴/σ⁴:
  // ≈ 0.91 (centroid) and 0.82 (trilinear) at Δ = σ, far above 0.05.
  const double fwhm = 0.06, sigma2 = fwhm * fwhm / (8 * std::numbers::ln2);
  for (PreDeposition kind : {PreDeposition::kCentroid, PreDeposition::kTrilinear})
    for (double ratio : {0.5, 1.0}) {
      const double h = ratio * std::sqrt(sigma2), r2 = ratio * ratio;
      const double c = kernel_variance_per_h2(kind);
      const double k4_kernel = kind == PreDeposition::kCentroid ? -1.0 / 120 : -1.0 / 60;
      const KernelMoments k = measure(kind, h, fwhm, FilterIntegration::kExact, 0);
      EXPECT_NEAR(k.excess_kurtosis, r2 - (c - k4_kernel) * r2 * r2, 2e-3) << pre_deposition_name(kind) << ratio;
      if (ratio == 1.0) {
        EXPECT_GT(k.excess_kurtosis, 0.8);
      }
    }
}

TEST(TransferKernel, GaussianIntegrationHasTheTargetVarianceAndNoExcessKurtosis) {
  const double fwhm = 0.06, sigma2 = fwhm * fwhm / (8 * std::numbers::ln2);
  for (PreDeposition kind : {PreDeposition::kCentroid, PreDeposition::kTrilinear})
    for (double ratio : {0.25, 0.5, 1.0, 1.3}) {  // Δ/σ
      const double h = ratio * std::sqrt(sigma2);
      const double c = kernel_variance_per_h2(kind);
      const double s2 = sigma2 - c * h * h;  // 2ν, the sampled Gaussian's nominal variance
      const double s_over_h = std::sqrt(s2) / h;
      const double aliasing = s2 - sampled_gaussian_variance_h2(s_over_h) * h * h;  // s²ε ≥ 0
      const double bound = s2 * 8 * std::numbers::pi * std::numbers::pi * s_over_h * s_over_h *
                           std::exp(-2 * std::numbers::pi * std::numbers::pi * s_over_h * s_over_h);
      EXPECT_LE(aliasing, bound + 1e-15 * s2) << ratio;
      const KernelMoments k = measure(kind, h, fwhm, FilterIntegration::kGaussian, 0);
      const double midpoint = h * h / (12.0 * 64 * 64) * (kind == PreDeposition::kCentroid ? -1 : 1);
      // Transforms and round-off only: 1e-9 σ² as above.
      EXPECT_NEAR(k.variance, sigma2 + midpoint - aliasing, 1e-9 * sigma2) << pre_deposition_name(kind) << ratio;
      // Within 1 % of σ² while Δ ≤ 1.3σ (ε ≤ 0.8 % there, docs/TRANSFER.md).
      EXPECT_NEAR(k.variance, sigma2, 0.01 * sigma2);
      const double k4_kernel = kind == PreDeposition::kCentroid ? -1.0 / 120 : -1.0 / 60;
      const double r4 = std::pow(ratio, 4);
      if (ratio <= 1.0) {
        // The pre-deposition's cumulant alone (midpoint rule O(1/M²): 2e-3 as above).
        EXPECT_NEAR(k.excess_kurtosis, k4_kernel * r4, 2e-3) << pre_deposition_name(kind) << ratio;
        EXPECT_LE(std::fabs(k.excess_kurtosis), 0.05) << pre_deposition_name(kind) << ratio;
      }
    }
}

}  // namespace
}  // namespace gridfree
