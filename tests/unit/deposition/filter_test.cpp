// SPDX-License-Identifier: GPL-3.0-or-later
// The diffusion filter (PHYSICS.md §3.2): diffusivities, conservation,
// symmetry of periodic wrap and of zero-flux walls, and the no-op case.
// The statistical checks (variance per step, Gaussian profile) are in
// tests/verification/deposition/filter_gaussian_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "deposition/filter.h"

namespace gridfree {
namespace {

Grid line_grid(int n, double length, bool periodic) {
  Grid g;
  g.n = {n, 1, 1};
  g.length = {length, 1, 1};
  g.periodic = {periodic, false, false};
  return g;
}

long double total(const std::vector<double>& f) {
  long double s = 0;
  for (double v : f) s += v;
  return s;
}

std::vector<double> random_field(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> f(n);
  for (double& v : f) v = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return f;
}

TEST(FilterDiffusivity, SeedAndMfixFormulas) {
  Grid g;
  g.n = {10, 20, 5};
  g.length = {1.0, 3.0, 2.0};  // Δ = (0.1, 0.15, 0.4): non-cubic cells
  FilterSettings s;
  s.fwhm_cm = 0.3;
  const auto nu = filter_diffusivity(g, s);
  const double ln2 = std::log(2.0);
  // ν_i = (δ² − Δ_i²)/(16 ln 2) per direction; Δ_z > δ_f gives 0.
  EXPECT_NEAR(nu[0], (0.09 - 0.01) / (16 * ln2), 1e-15);
  EXPECT_NEAR(nu[1], (0.09 - 0.0225) / (16 * ln2), 1e-15);
  EXPECT_EQ(nu[2], 0.0);
  s.diffusivity = FilterDiffusivity::kMfix;
  const auto nu_mfix = filter_diffusivity(g, s);
  for (double v : nu_mfix) EXPECT_NEAR(v, 0.09 / (8 * std::sqrt(2 * ln2)), 1e-15);
}

TEST(FilterDiffusivity, MfixIsAboutOnePointOneEightTimesSeedForSmallCells) {
  // (16 ln 2)/(8 √(2 ln 2)) = 11.09/9.42 ≈ 1.177; at Δ = 1e-6 δ_f the seed's
  // −Δ² changes ν by 1e-12 relative.
  const Grid g = line_grid(1000000, 1.0, true);  // Δ = 1e-6 cm
  FilterSettings seed;
  seed.fwhm_cm = 1.0;
  FilterSettings mfix = seed;
  mfix.diffusivity = FilterDiffusivity::kMfix;
  const double ratio = filter_diffusivity(g, mfix)[0] / filter_diffusivity(g, seed)[0];
  const double expected = 16 * std::log(2.0) / (8 * std::sqrt(2 * std::log(2.0)));
  EXPECT_NEAR(ratio, expected, 1e-10);
  EXPECT_NEAR(ratio, 1.177, 1e-3);
}

TEST(Filter, CellsAtLeastFilterWidthLeaveFieldUnchanged) {
  Grid g;
  g.n = {6, 5, 4};
  g.length = {6, 5, 4};  // Δ = 1 cm on every axis
  FilterSettings s;
  s.fwhm_cm = 1.0;  // δ_f = Δ: ν = 0
  auto field = random_field(g.cells(), 7);
  const auto before = field;
  const FilterStats stats = apply_filter(g, s, field);
  EXPECT_EQ(field, before);  // bit for bit
  EXPECT_EQ(stats.steps, 0);
  EXPECT_EQ(stats.total_iterations, 0);
  EXPECT_TRUE(stats.converged);
  s.fwhm_cm = 0.5;
  apply_filter(g, s, field);
  EXPECT_EQ(field, before);
}

TEST(Filter, ConservesTotalOnPeriodicAndWallGrids) {
  // Σ α V is conserved to round-off: the step matrix has unit column sums and
  // the solver removes the constant part of its residual. 1e-13 relative
  // allows ~500 roundings of the summed 10^3–10^4 terms.
  for (int walls = 0; walls < 2; ++walls)
    for (int steps : {1, 5}) {
      Grid g;
      g.n = {17, 12, 9};
      g.length = {1.7, 1.8, 0.9};  // Δ = (0.1, 0.15, 0.1)
      g.periodic = {walls == 0, false, walls == 0};
      FilterSettings s;
      s.fwhm_cm = 0.6;
      s.steps = steps;
      s.tolerance = 1e-6;  // loose on purpose: conservation must not rely on it
      auto field = random_field(g.cells(), 11 + steps);
      const long double before = total(field);
      const FilterStats stats = apply_filter(g, s, field);
      EXPECT_TRUE(stats.converged);
      EXPECT_EQ(stats.steps, steps);
      EXPECT_GT(stats.total_iterations, 0);
      EXPECT_LE(stats.worst_final_residual, 1e-6);
      EXPECT_NEAR(static_cast<double>(total(field)), static_cast<double>(before),
                  1e-13 * static_cast<double>(before))
          << "walls=" << walls << " steps=" << steps;
    }
}

TEST(Filter, PeriodicWrapIsSymmetricAcrossTheBoundary) {
  // A source in cell 0 of a periodic line spreads equally to cells k and n − k.
  const int n = 40;
  const Grid g = line_grid(n, 40.0, true);
  FilterSettings s;
  s.fwhm_cm = 6.0;
  s.steps = 3;
  s.tolerance = 1e-13;
  std::vector<double> field(n, 0.0);
  field[0] = 1.0;
  apply_filter(g, s, field);
  EXPECT_GT(field[n - 1], 0.1 * field[0]);  // it did cross the boundary
  // Agreement to the solve tolerance: ||e|| ≤ ||A⁻¹|| ||r|| ≤ 1e-13 ||b||.
  for (int k = 1; k < n; ++k) EXPECT_NEAR(field[k], field[n - k], 1e-12) << k;
}

TEST(Filter, ZeroFluxWallIsAMirror) {
  // Discrete reflection: on a wall-bounded line of n cells, the filtered
  // source in cell 0 equals the restriction of the filtered pair of sources
  // in cells n−1 and n (mirror images about the middle face) on a periodic
  // line of 2n cells, because the mirrored problem has no flux through that
  // face. The far mirror face (cells 0 and 2n−1) is handled by the wrap.
  const int n = 30;
  FilterSettings s;
  s.fwhm_cm = 8.0;
  s.steps = 4;
  s.tolerance = 1e-13;
  std::vector<double> wall(n, 0.0);
  wall[0] = 1.0;
  const FilterStats stats = apply_filter(line_grid(n, n, false), s, wall);
  std::vector<double> mirrored(2 * n, 0.0);
  mirrored[n - 1] = mirrored[n] = 1.0;
  apply_filter(line_grid(2 * n, 2 * n, true), s, mirrored);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(wall[i], mirrored[n + i], 1e-12) << i;
  EXPECT_NEAR(static_cast<double>(total(wall)), 1.0, 1e-14);
  EXPECT_NEAR(stats.nu[0], (64.0 - 1.0) / (16 * std::log(2.0)), 1e-14);
}

TEST(Filter, SingleCellAxesAreSkipped) {
  // A 40×1×1 grid filters like a line: identical result with y, z periodic or walls.
  FilterSettings s;
  s.fwhm_cm = 5.0;
  s.tolerance = 1e-13;
  Grid a = line_grid(40, 40.0, true);
  Grid b = a;
  b.periodic = {true, true, true};
  b.length = {40.0, 0.5, 0.5};  // ν_y, ν_z > 0, but one cell each
  std::vector<double> fa(40, 0.0), fb(40, 0.0);
  fa[5] = fb[5] = 2.0;
  apply_filter(a, s, fa);
  apply_filter(b, s, fb);
  for (int i = 0; i < 40; ++i) EXPECT_NEAR(fa[i], fb[i], 1e-13);
}

TEST(Filter, StaysNonNegativeAndSmooths) {
  // Backward Euler with this M-matrix preserves positivity; the solution is
  // accurate to 1e-13 of ||b||, so values are ≥ −1e-12. The maximum drops.
  Grid g;
  g.n = {16, 16, 16};
  g.length = {1.6, 1.6, 1.6};
  g.periodic = {true, false, true};
  FilterSettings s;
  s.fwhm_cm = 0.5;
  s.tolerance = 1e-13;
  auto field = random_field(g.cells(), 3);
  for (std::size_t c = 0; c < field.size(); c += 3) field[c] = 0;
  double max_before = 0;
  for (double v : field) max_before = std::max(max_before, v);
  apply_filter(g, s, field);
  double max_after = 0;
  for (double v : field) {
    EXPECT_GE(v, -1e-12);
    max_after = std::max(max_after, v);
  }
  EXPECT_LT(max_after, 0.9 * max_before);
}

// A 12 × 10 × 8 box of 0.1 cm cells and a 0.4 cm filter solved to 1e-12.
Grid box_12_10_8(std::array<bool, 3> periodic) {
  Grid g;
  g.n = {12, 10, 8};
  g.length = {1.2, 1.0, 0.8};
  g.periodic = periodic;
  return g;
}

FilterSettings tight_settings(int steps) {
  FilterSettings s;
  s.fwhm_cm = 0.4;
  s.steps = steps;
  s.tolerance = 1e-12;
  return s;
}

TEST(Filter, ReusableFilterMatchesOneShotFilter) {
  // One DiffusionFilter applied to several fields (the set-up reused) gives
  // what apply_filter gives for each; both solve to 1e-12, so they agree to
  // ~1e-12 of the field scale (values here are O(1)).
  const Grid g = box_12_10_8({true, false, false});
  const FilterSettings s = tight_settings(2);
  DiffusionFilter reusable(g, s);
  DiffusionFilter moved = std::move(reusable);
  EXPECT_TRUE(moved.active());
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    auto a = random_field(g.cells(), seed);
    auto b = a;
    const FilterStats sa = moved.apply(a);
    const FilterStats sb = apply_filter(g, s, b);
    EXPECT_EQ(sa.steps, sb.steps);
    EXPECT_EQ(sa.nu, sb.nu);
    for (std::size_t c = 0; c < a.size(); ++c) EXPECT_NEAR(a[c], b[c], 1e-11);
  }
  FilterSettings narrow = s;
  narrow.fwhm_cm = 0.05;  // below every Δ_i
  EXPECT_FALSE(DiffusionFilter(g, narrow).active());
}

TEST(Filter, WarmStartGivesTheColdResultInFewerIterations) {
  // A field filtered, then changed by 1e-4 of its size and filtered again
  // from the first call's step results: the same answer as a cold filter of
  // the changed field (both meet ||r|| ≤ 1e-12 ||α^n|| per step, so they
  // agree to ~1e-11 here), in fewer linear iterations; conservation holds.
  const Grid g = box_12_10_8({true, false, true});
  DiffusionFilter filter(g, tight_settings(4));
  FilterWarmStart warm;
  auto first = random_field(g.cells(), 7);
  const auto unfiltered = first;
  filter.apply(first, warm);
  ASSERT_EQ(warm.steps.size(), 4u);
  auto changed = unfiltered;
  const auto noise = random_field(g.cells(), 8);
  for (std::size_t c = 0; c < changed.size(); ++c) changed[c] += 1e-4 * noise[c];
  auto cold = changed;
  const FilterStats s_cold = filter.apply(cold);
  const FilterStats s_warm = filter.apply(changed, warm);
  EXPECT_LT(s_warm.total_iterations, s_cold.total_iterations);
  double sum_in = 0, sum_out = 0;
  for (std::size_t c = 0; c < cold.size(); ++c) {
    EXPECT_NEAR(changed[c], cold[c], 1e-11);
    sum_in += unfiltered[c] + 1e-4 * noise[c];
    sum_out += changed[c];
  }
  EXPECT_NEAR(sum_out, sum_in, 1e-10 * std::abs(sum_in));
}

}  // namespace
}  // namespace gridfree
