// SPDX-License-Identifier: GPL-3.0-or-later
// Gaussian filter integration (deposition/filter.h, FilterIntegration::
// kGaussian) in real space: the filtered unit impulse is the normalised
// sampled Gaussian g_m of variance s² = 2ν (periodised on a periodic axis,
// plus its images in the wall faces on a wall-bounded one), positive, and
// Σ is conserved to round-off; in 3-D it is the product of the axes' kernels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "deposition/filter.h"

namespace gridfree {
namespace {

Grid line(int n, double h, bool periodic) {
  Grid g;
  g.n = {n, 1, 1};
  g.length = {n * h, h, h};
  g.periodic = {periodic, true, true};
  return g;
}

FilterSettings gaussian_settings(double fwhm) {
  FilterSettings s;
  s.fwhm_cm = fwhm;
  s.diffusivity = FilterDiffusivity::kConsistent;
  s.kernel_variance_per_h2 = 1.0 / 6.0;
  s.integration = FilterIntegration::kGaussian;
  return s;
}

// Σ over the 2n-periodic images (periodic: n-periodic) of exp(−d²/(2s²)),
// d in cells, normalised over the line: the expected kernel, built directly.
std::vector<double> expected_kernel(int n, int source, double s_over_h, bool periodic) {
  std::vector<double> k(std::size_t(n), 0.0);
  const int period = periodic ? n : 2 * n;
  for (int i = 0; i < n; ++i)
    for (int q = -40; q <= 40; ++q) {
      const double d = i - source - q * period;
      k[std::size_t(i)] += std::exp(-d * d / (2 * s_over_h * s_over_h));
      if (!periodic) {
        const double e = i - (-1 - source) - q * period;  // the image in the face at 0
        k[std::size_t(i)] += std::exp(-e * e / (2 * s_over_h * s_over_h));
      }
    }
  double sum = 0;
  for (double v : k) sum += v;
  for (double& v : k) v /= sum;
  return k;
}

TEST(GaussianFilter, ImpulseResponseIsTheSampledGaussianWithWallImages) {
  const double fwhm = 0.06;
  for (double h : {0.005, 0.02, 0.03})  // Δ/σ ≈ 0.2, 0.8, 1.2
    for (bool periodic : {true, false}) {
      const int n = 40;
      const Grid g = line(n, h, periodic);
      const FilterSettings s = gaussian_settings(fwhm);
      DiffusionFilter f(g, s);
      const double s_over_h = std::sqrt(2 * f.nu()[0]) / h;
      for (int source : {0, 3, 17}) {
        std::vector<double> field(std::size_t(n), 0.0);
        field[std::size_t(source)] = 1.0;
        f.apply(field);
        const std::vector<double> want = expected_kernel(n, source, s_over_h, periodic);
        double total = 0;
        for (int i = 0; i < n; ++i) {
          // Transform round-off: a few ulps of the O(1) total per entry.
          EXPECT_NEAR(field[std::size_t(i)], want[std::size_t(i)], 1e-15 * 40)
              << "h " << h << " periodic " << periodic << " source " << source << " i " << i;
          total += field[std::size_t(i)];
        }
        EXPECT_NEAR(total, 1.0, 1e-14);
        const double mx = *std::max_element(field.begin(), field.end());
        EXPECT_GE(*std::min_element(field.begin(), field.end()), -1e-14 * mx);
      }
    }
}

TEST(GaussianFilter, ThreeDimensionalKernelIsTheProductOfTheAxesAndConserves) {
  Grid g;
  g.n = {12, 16, 10};
  g.length = {12 * 0.02, 16 * 0.015, 10 * 0.025};
  g.periodic = {true, false, true};
  const FilterSettings s = gaussian_settings(0.06);
  DiffusionFilter f(g, s);
  const int src[3] = {5, 2, 9};
  std::vector<double> field(g.cells(), 0.0);
  field[g.index(src[0], src[1], src[2])] = 1.0;
  f.apply(field);
  std::array<std::vector<double>, 3> axis;
  for (int a = 0; a < 3; ++a)
    axis[std::size_t(a)] = expected_kernel(g.n[a], src[a], std::sqrt(2 * f.nu()[std::size_t(a)]) / g.h(a), g.periodic[a]);
  long double total = 0;
  double mx = 0, mn = 1;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double v = field[g.index(i, j, k)];
        EXPECT_NEAR(v, axis[0][std::size_t(i)] * axis[1][std::size_t(j)] * axis[2][std::size_t(k)], 1e-15);
        total += v;
        mx = std::max(mx, v);
        mn = std::min(mn, v);
      }
  EXPECT_NEAR(double(total), 1.0, 1e-14);
  EXPECT_GE(mn, -1e-14 * mx);
}

TEST(GaussianFilter, SameNuAsTheOtherIntegrationsAndIdentityWhenNoAxisDiffuses) {
  Grid g = line(20, 0.02, true);
  FilterSettings s = gaussian_settings(0.06);
  FilterSettings e = s;
  e.integration = FilterIntegration::kExact;
  EXPECT_EQ(DiffusionFilter(g, s).nu(), DiffusionFilter(g, e).nu());
  // Δ ≥ σ√6 with the trilinear kernel: ν = 0 on every axis, the field is untouched.
  const Grid coarse = line(20, 0.07, true);
  DiffusionFilter none(coarse, s);
  EXPECT_FALSE(none.active());
  std::vector<double> field(20, 0.0);
  field[3] = 1.0;
  const std::vector<double> before = field;
  none.apply(field);
  EXPECT_EQ(field, before);
}

}  // namespace
}  // namespace gridfree
