// SPDX-License-Identifier: GPL-3.0-or-later
// The diffusion filter as a Gaussian filter (PHYSICS.md §3.2).
//
// 1. Variance: on an unbounded line, one backward-Euler step of
//    (I − c δ²) α' = α (c = ν Δτ/Δ²) conserves Σα and Σα x and adds exactly
//    2 ν Δτ to Σα x²/Σα, because Σ x_i² δ²α_i = Σ α_i δ²(x²)_i = 2Δ² Σα_i
//    (summation by parts). So after τ = 1 the variance grew by 2ν for any
//    number of steps. A periodic line long enough that the tails never wrap
//    stands in for the unbounded one.
// 2. Profile: a unit point source (mass in one cell) approaches the Gaussian
//    of variance Δ²/12 + 2ν (the cell's own box, plus diffusion). The
//    deviation is governed by the fourth cumulant of the discrete kernel:
//    per step the cumulant generating function is −ln(1 − c(2cosh(sΔ) − 2)),
//    whose s⁴ coefficient gives κ4 = 2cΔ⁴ + 12c²Δ⁴, i.e. over K steps
//    κ4 = 2νΔ² + 12ν²/K (the box adds −Δ⁴/120). By the Edgeworth expansion
//    the density differs from the Gaussian by κ4/(24σ⁴) He4(x/σ) G(x), at
//    most κ4/(8σ⁴) G(0) (at x = 0); sampling at cell centres instead of
//    averaging adds Δ²/(24σ²) G(0). The tolerance is 1.5× the sum of the
//    two (the 1.5 covers the O(σ⁻⁴) terms, a few % of the bound here).
// 3. The zero-flux wall: a source against the wall stays in the domain and
//    its profile is the Gaussian plus its mirror image about the wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "deposition/filter.h"

namespace gridfree {
namespace {

Grid line_grid(int n, double dx, bool periodic) {
  Grid g;
  g.n = {n, 1, 1};
  g.length = {n * dx, 1, 1};
  g.periodic = {periodic, false, false};
  return g;
}

double gaussian(double x, double variance) {
  return std::exp(-x * x / (2 * variance)) / std::sqrt(2 * std::numbers::pi * variance);
}

struct Moments {
  double mass = 0, mean = 0, variance = 0;
};

// Moments of m_i along positions x_i (relative coordinates, no wrap).
Moments moments(const std::vector<double>& m, const std::vector<double>& x) {
  long double s0 = 0, s1 = 0, s2 = 0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    s0 += m[i];
    s1 += m[i] * x[i];
    s2 += m[i] * x[i] * x[i];
  }
  Moments r;
  r.mass = static_cast<double>(s0);
  r.mean = static_cast<double>(s1 / s0);
  r.variance = static_cast<double>(s2 / s0 - (s1 / s0) * (s1 / s0));
  return r;
}

TEST(FilterGaussian, EachStepAddsExactlyTwoNuDtauOfVariance) {
  // Line of 400 cells of 1 cm, δ_f = 8 cm: ν = 63/(16 ln 2) ≈ 5.68 cm². The
  // slowest tail (one step) decays like 0.66^k per cell, ~1e-36 at the
  // half-length: the wrap is invisible. Errors come from the linear solves:
  // ||e|| ≤ ||A⁻¹|| ||r|| ≤ 1e-13 ||b|| per step (λ_min(A) = 1), worth
  // ≤ 1e-13 (Σx⁴)^½ ≈ 2e-8 cm² of variance per step; tolerance 1e-6 cm².
  const int n = 400;
  const Grid g = line_grid(n, 1.0, true);
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = g.centre(0, i) - g.centre(0, n / 2);
  for (int steps : {1, 3, 20}) {
    FilterSettings s;
    s.fwhm_cm = 8.0;
    s.steps = steps;
    s.tolerance = 1e-13;
    std::vector<double> field(n, 0.0);
    field[n / 2] = 1.0;
    const FilterStats stats = apply_filter(g, s, field);
    ASSERT_TRUE(stats.converged);
    const Moments m = moments(field, x);
    const double two_nu = 2 * stats.nu[0];
    EXPECT_NEAR(two_nu, 2 * 63.0 / (16 * std::log(2.0)), 1e-12);
    EXPECT_NEAR(m.mass, 1.0, 1e-14);
    EXPECT_NEAR(m.mean, 0.0, 1e-9);
    EXPECT_NEAR(m.variance, two_nu, 1e-6) << steps << " steps";
    std::printf("steps %2d: variance %.12f, 2 nu %.12f, %d iterations\n", steps, m.variance, two_nu,
                stats.total_iterations);
  }
}

TEST(FilterGaussian, NonCubicCellsUseTheirOwnSpacingPerDirection) {
  // Δ = (1, 1.5, 2) cm, δ_f = 6 cm, 2 steps; periodic box of 80×60×40 cells
  // (80, 90, 80 cm), a unit source in one cell. The variance along each axis
  // grows by 2ν_i with ν_i = (δ_f² − Δ_i²)/(16 ln 2), and the axes stay
  // uncorrelated. The two-step kernel decays by ≥ 0.46 per cell (x), so the
  // mass beyond the half-lengths is ~1e-13 and, weighted by x² ~ 1600 cm²,
  // moves the variances by far less than the tolerance 1e-7 cm² (a 40×30-cell
  // y–z box was measurably contaminated, 1.6e-7 cm²).
  Grid g;
  g.n = {80, 60, 40};
  g.length = {80.0, 90.0, 80.0};
  g.periodic = {true, true, true};
  FilterSettings s;
  s.fwhm_cm = 6.0;
  s.steps = 2;
  s.tolerance = 1e-13;
  std::vector<double> field(g.cells(), 0.0);
  const int ci = 40, cj = 30, ck = 20;
  field[g.index(ci, cj, ck)] = 1.0;
  const FilterStats stats = apply_filter(g, s, field);
  ASSERT_TRUE(stats.converged);
  long double m0 = 0, mxx = 0, myy = 0, mzz = 0, mxy = 0;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double a = field[g.index(i, j, k)];
        const double dx = (i - ci) * g.h(0), dy = (j - cj) * g.h(1), dz = (k - ck) * g.h(2);
        m0 += a;
        mxx += a * dx * dx;
        myy += a * dy * dy;
        mzz += a * dz * dz;
        mxy += a * dx * dy;
      }
  const double ln2 = std::log(2.0);
  const double expected[3] = {2 * (36.0 - 1.0) / (16 * ln2), 2 * (36.0 - 2.25) / (16 * ln2),
                              2 * (36.0 - 4.0) / (16 * ln2)};
  EXPECT_NEAR(static_cast<double>(m0), 1.0, 1e-13);
  EXPECT_NEAR(static_cast<double>(mxx / m0), expected[0], 1e-7);
  EXPECT_NEAR(static_cast<double>(myy / m0), expected[1], 1e-7);
  EXPECT_NEAR(static_cast<double>(mzz / m0), expected[2], 1e-7);
  EXPECT_NEAR(static_cast<double>(mxy / m0), 0.0, 1e-9);
}

// Tolerance of item 2 of the header for K steps of ν on cells of Δ.
double profile_tolerance(double nu, double dx, int steps, double variance) {
  const double kappa4 = 2 * nu * dx * dx + 12 * nu * nu / steps + dx * dx * dx * dx / 120;
  const double peak = gaussian(0.0, variance);
  return 1.5 * peak * (kappa4 / (8 * variance * variance) + dx * dx / (24 * variance));
}

TEST(FilterGaussian, ManySmallStepsGiveTheGaussianOfWidthFwhm) {
  // δ_f = 16 cm on 1 cm cells: ν = 255/(16 ln 2) ≈ 23 cm², σ ≈ 6.8 cm;
  // 200 steps; line of 400 cells (the tails at ±200 cm are ~e^-430).
  const int n = 400, steps = 200;
  const double dx = 1.0;
  const Grid g = line_grid(n, dx, true);
  FilterSettings s;
  s.fwhm_cm = 16.0;
  s.steps = steps;
  s.tolerance = 1e-12;
  std::vector<double> field(n, 0.0);
  field[n / 2] = 1.0 / dx;  // unit mass
  const FilterStats stats = apply_filter(g, s, field);
  ASSERT_TRUE(stats.converged);
  const double nu = stats.nu[0];
  const double variance = dx * dx / 12 + 2 * nu;
  double max_error = 0;
  for (int i = 0; i < n; ++i) {
    const double x = g.centre(0, i) - g.centre(0, n / 2);
    max_error = std::max(max_error, std::abs(field[i] - gaussian(x, variance)));
  }
  const double tolerance = profile_tolerance(nu, dx, steps, variance);
  std::printf("max |alpha - G| = %.3e (peak %.4f, tolerance %.3e)\n", max_error, gaussian(0, variance),
              tolerance);
  EXPECT_LT(max_error, tolerance);
  // Its FWHM: the measured lattice variance (2ν) plus the cell's Δ²/12 gives
  // 8 ln 2 (Δ²/12 + 2ν) = δ_f² − (1 − 8 ln 2/12) Δ², so the FWHM is δ_f up to
  // a relative 0.27 Δ²/δ_f² (1.1e-3 here); tolerance 0.3 Δ²/δ_f² relative.
  std::vector<double> x(n), mass(n);
  for (int i = 0; i < n; ++i) {
    x[i] = g.centre(0, i) - g.centre(0, n / 2);
    mass[i] = field[i] * dx;
  }
  const double fwhm = std::sqrt(8 * std::log(2.0) * (moments(mass, x).variance + dx * dx / 12));
  EXPECT_NEAR(fwhm, 16.0, 16.0 * 0.3 * dx * dx / (16.0 * 16.0));
  EXPECT_LT(fwhm, 16.0);
}

TEST(FilterGaussian, ZeroFluxWallReflectsTheGaussian) {
  // Source in the first cell of a wall-bounded line (centre x = Δ/2): the
  // profile is G(x − Δ/2) + G(x + Δ/2); all mass stays. Same tolerance as
  // above, doubled for the two images.
  const int n = 200, steps = 200;
  const double dx = 1.0;
  const Grid g = line_grid(n, dx, false);
  FilterSettings s;
  s.fwhm_cm = 16.0;
  s.steps = steps;
  s.tolerance = 1e-12;
  std::vector<double> field(n, 0.0);
  field[0] = 1.0 / dx;
  const FilterStats stats = apply_filter(g, s, field);
  ASSERT_TRUE(stats.converged);
  const double variance = dx * dx / 12 + 2 * stats.nu[0];
  long double mass = 0;
  double max_error = 0;
  for (int i = 0; i < n; ++i) {
    mass += field[i] * dx;
    const double x = g.centre(0, i);
    const double reflected = gaussian(x - 0.5 * dx, variance) + gaussian(x + 0.5 * dx, variance);
    max_error = std::max(max_error, std::abs(field[i] - reflected));
  }
  const double tolerance = 2 * profile_tolerance(stats.nu[0], dx, steps, variance);
  std::printf("wall: max |alpha - reflected G| = %.3e (tolerance %.3e)\n", max_error, tolerance);
  EXPECT_NEAR(static_cast<double>(mass), 1.0, 1e-13);
  EXPECT_LT(max_error, tolerance);
}

TEST(FilterGaussian, SourceNextToPeriodicBoundarySpreadsSymmetricallyAcrossIt) {
  // Source in the last cell of a periodic line: cells n−1−k and k−1 (k ≥ 1)
  // are at the same distance across the boundary face and must agree; the
  // profile matches the same Gaussian as in the middle of the line.
  const int n = 100, steps = 50;
  const Grid g = line_grid(n, 1.0, true);
  FilterSettings s;
  s.fwhm_cm = 10.0;
  s.steps = steps;
  s.tolerance = 1e-13;
  std::vector<double> field(n, 0.0);
  field[n - 1] = 1.0;
  const FilterStats stats = apply_filter(g, s, field);
  ASSERT_TRUE(stats.converged);
  for (int k = 1; k < n / 2; ++k) EXPECT_NEAR(field[n - 1 - k], field[k - 1], 1e-12) << k;
  const double variance = 1.0 / 12 + 2 * stats.nu[0];
  const double tolerance = profile_tolerance(stats.nu[0], 1.0, steps, variance);
  for (int k = 0; k < n / 2; ++k) EXPECT_NEAR(field[k], gaussian(k + 1.0, variance), tolerance) << k;
}

}  // namespace
}  // namespace gridfree
