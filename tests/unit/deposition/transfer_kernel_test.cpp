// SPDX-License-Identifier: GPL-3.0-or-later
// Transfer kernels (deposition/kernel_weights.h, transfer_stencils.h):
// weights sum to 1, trilinear reproduces linear functions and has the
// second moment t(1 − t)Δ², the gaussian cell integrals have mean x and
// variance σ² + Δ²/12 (cell averaging), folding conserves weight, and
// deposition and sampling are exact adjoints (Σ_c V q_c φ_c = Σ_p q_p φ(x_p)).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "deposition/kernel_weights.h"
#include "deposition/transfer_stencils.h"

namespace gridfree {
namespace {

double sum(const AxisWeights& w) { return std::accumulate(w.weight.begin(), w.weight.end(), 0.0); }

TEST(TrilinearWeights, SumToOneReproduceLinearAndHaveTentVariance) {
  const double h = 0.3;
  for (double x : {1.0, 1.05, 1.2, 1.3499, 2.71}) {
    const AxisWeights w = trilinear_weights(x, h);
    double m1 = 0, m2 = 0;
    for (std::size_t m = 0; m < w.cell.size(); ++m) {
      const double xi = (w.cell[m] + 0.5) * h;
      m1 += w.weight[m] * xi;
      m2 += w.weight[m] * (xi - x) * (xi - x);
    }
    const double t = x / h - 0.5 - std::floor(x / h - 0.5);
    EXPECT_NEAR(sum(w), 1.0, 1e-15);
    EXPECT_NEAR(m1, x, 1e-14);                      // linear functions are reproduced
    EXPECT_NEAR(m2, t * (1 - t) * h * h, 1e-14);    // second moment of the two-point split
  }
}

TEST(GaussianWeights, NormalisedWithMeanAndVarianceOfTheCellAveragedGaussian) {
  const double h = 0.1, sigma = 0.37, x = 2.0333;
  const AxisWeights w = gaussian_weights(x, h, sigma, 6.0);
  double m1 = 0, m2 = 0;
  for (std::size_t m = 0; m < w.cell.size(); ++m) {
    const double xi = (w.cell[m] + 0.5) * h;
    m1 += w.weight[m] * xi;
    m2 += w.weight[m] * (xi - x) * (xi - x);
  }
  EXPECT_NEAR(sum(w), 1.0, 4e-16 * double(w.cell.size()));
  // Centre-of-cell moments of cell integrals: mean x + O(e^{−2π²σ²/h²}) and
  // variance σ² + h²/12 (Sheppard's correction); truncation at 6σ changes
  // them by < 1e-7 relative.
  EXPECT_NEAR(m1, x, 1e-9);
  EXPECT_NEAR(m2, sigma * sigma + h * h / 12, 1e-7 * sigma * sigma);
}

TEST(FoldAxisWeights, WrapsOnPeriodicAxesAndReflectsAtWalls) {
  const AxisWeights raw{{-2, -1, 0, 4, 5}, {0.1, 0.2, 0.3, 0.15, 0.25}};
  const AxisWeights wall = fold_axis_weights(raw, 5, false);
  // −1 → 0, −2 → 1, 5 → 4 (images across the walls at 0 and 5Δ).
  EXPECT_EQ(wall.cell, (std::vector<int>{0, 1, 4}));
  EXPECT_NEAR(wall.weight[0], 0.5, 1e-15);
  EXPECT_NEAR(wall.weight[1], 0.1, 1e-15);
  EXPECT_NEAR(wall.weight[2], 0.4, 1e-15);
  const AxisWeights wrap = fold_axis_weights(raw, 5, true);
  // −1 → 4, −2 → 3, 5 → 0.
  EXPECT_EQ(wrap.cell, (std::vector<int>{0, 3, 4}));
  EXPECT_NEAR(wrap.weight[0], 0.55, 1e-15);
  EXPECT_NEAR(wrap.weight[1], 0.1, 1e-15);
  EXPECT_NEAR(wrap.weight[2], 0.35, 1e-15);
}

class StencilsTest : public ::testing::TestWithParam<PreDeposition> {};

TEST_P(StencilsTest, DepositionConservesAndIsTheAdjointOfSampling) {
  Grid g;
  g.n = {7, 9, 4};
  g.length = {0.7, 0.45, 0.4};  // Δ = (0.1, 0.05, 0.1); walls in y
  g.periodic = {true, false, true};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Particle> ps;
  for (int p = 0; p < 40; ++p) ps.push_back({u(rng) * 0.7, u(rng) * 0.45, u(rng) * 0.4, 0.02});
  ps.push_back({0.0, 0.0, 0.4, 0.02});  // on the walls and the periodic seam
  KernelParams k{GetParam(), 0.08, 4};
  const TransferStencils s(g, ps, k);
  std::vector<double> q(ps.size()), phi(g.cells());
  for (double& v : q) v = u(rng);
  for (double& v : phi) v = u(rng) - 0.5;
  std::vector<double> field;
  s.deposit(q, field);
  long double mass = 0, inner_grid = 0, inner_particles = 0, total = 0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    mass += field[c] * g.cell_volume();
    inner_grid += field[c] * g.cell_volume() * phi[c];
  }
  for (std::size_t p = 0; p < ps.size(); ++p) {
    total += q[p];
    inner_particles += q[p] * s.sample(p, phi);
    EXPECT_NEAR(s.total_weight(p), 1.0, 1e-14);
  }
  // Round-off of ~10^3 products of O(1) numbers.
  EXPECT_NEAR(double(mass), double(total), 1e-13 * double(total));
  EXPECT_NEAR(double(inner_grid), double(inner_particles), 1e-13 * double(total));
}

INSTANTIATE_TEST_SUITE_P(Kernels, StencilsTest,
                         ::testing::Values(PreDeposition::kCentroid, PreDeposition::kTrilinear,
                                           PreDeposition::kGaussian));

TEST(KernelVariance, CentroidTwelfthTrilinearSixthGaussianNone) {
  EXPECT_DOUBLE_EQ(kernel_variance_per_h2(PreDeposition::kCentroid), 1.0 / 12);
  EXPECT_DOUBLE_EQ(kernel_variance_per_h2(PreDeposition::kTrilinear), 1.0 / 6);
  EXPECT_DOUBLE_EQ(kernel_variance_per_h2(PreDeposition::kGaussian), 0.0);
}

}  // namespace
}  // namespace gridfree
