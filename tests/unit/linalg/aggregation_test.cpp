// SPDX-License-Identifier: GPL-3.0-or-later
// Aggregation coarsening (linalg/aggregation.h): the coarse operator equals
// the Galerkin product Pᵀ A P formed here with dense matrices from the
// definition of P (P_iI = 1 if fine cell i lies in aggregate I), row sums
// are preserved, restriction is the transpose of prolongation, and periodic
// axes stay periodic.
#include "linalg/aggregation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "linalg/model_problems.h"
#include "linalg/stencil_ops.h"
#include "test_grids.h"

namespace gridfree {
namespace {

using Dense = std::vector<std::vector<double>>;

// Dense matrix of a stencil from its product with unit vectors.
Dense dense(const Stencil7& s) {
  const std::size_t n = s.grid.cells();
  Dense a(n, std::vector<double>(n, 0.0));
  std::vector<double> e(n, 0.0), col;
  for (std::size_t j = 0; j < n; ++j) {
    e[j] = 1;
    stencil_apply(s, e, col);
    for (std::size_t i = 0; i < n; ++i) a[i][j] = col[i];
    e[j] = 0;
  }
  return a;
}

using test_support::box_grid;

class LinalgGalerkin
    : public ::testing::TestWithParam<std::tuple<std::array<int, 3>, std::array<bool, 3>>> {};

TEST_P(LinalgGalerkin, CoarseOperatorIsPtAP) {
  const auto& [n, periodic] = GetParam();
  Grid g = box_grid(n, periodic);
  g.length = {double(n[0]), double(n[1]), double(n[2])};  // cubic cells: no semi-coarsening
  std::vector<double> kappa(g.cells());
  for (std::size_t c = 0; c < kappa.size(); ++c) kappa[c] = 1 + std::fmod(0.37 * double(c), 3.0);
  const Stencil7 fine =
      diffusion_stencil(g, kappa, DirichletSides{true, false, false, true, false, false}, 0.5);
  const Aggregation agg = choose_aggregation(fine, 0.25);
  Stencil7 coarse(agg.coarse);
  aggregate_coefficients(fine, agg, coarse);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(agg.coarse.n[a], n[a] >= 2 ? n[a] / 2 : 1);
    EXPECT_EQ(agg.coarse.periodic[a], periodic[a] && agg.coarse.n[a] > 1);
  }
  const Dense a = dense(fine);
  const Dense ac = dense(coarse);
  const std::size_t nf = g.cells(), nc = agg.coarse.cells();
  std::vector<std::size_t> owner(nf);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        owner[g.index(i, j, k)] = agg.coarse.index(agg.map[0][i], agg.map[1][j], agg.map[2][k]);
  Dense ptap(nc, std::vector<double>(nc, 0.0));
  for (std::size_t i = 0; i < nf; ++i)
    for (std::size_t j = 0; j < nf; ++j) ptap[owner[i]][owner[j]] += a[i][j];
  // Sums of O(10) terms of size O(1): a few ulps.
  for (std::size_t I = 0; I < nc; ++I)
    for (std::size_t J = 0; J < nc; ++J) EXPECT_NEAR(ac[I][J], ptap[I][J], 1e-12) << I << "," << J;
  EXPECT_LT(stencil_asymmetry(coarse), 1e-14);

  // Restriction = Pᵀ, prolongation = P: (P x_c, y_f) = (x_c, Pᵀ y_f).
  std::vector<double> xc(nc), yf(nf), restricted, prolonged(nf, 0.0);
  for (std::size_t I = 0; I < nc; ++I) xc[I] = std::cos(double(I));
  for (std::size_t i = 0; i < nf; ++i) yf[i] = std::sin(1.3 * double(i));
  restrict_sum(g, agg, yf, restricted);
  prolong_add(g, agg, 1.0, xc, prolonged);
  double lhs = 0, rhs = 0;
  for (std::size_t i = 0; i < nf; ++i) lhs += prolonged[i] * yf[i];
  for (std::size_t I = 0; I < nc; ++I) rhs += xc[I] * restricted[I];
  EXPECT_NEAR(lhs, rhs, 1e-12);
  for (std::size_t i = 0; i < nf; ++i) EXPECT_EQ(prolonged[i], xc[owner[i]]);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, LinalgGalerkin,
    ::testing::Values(
        std::make_tuple(std::array<int, 3>{4, 6, 2}, std::array<bool, 3>{true, false, true}),
        std::make_tuple(std::array<int, 3>{5, 7, 3}, std::array<bool, 3>{true, false, true}),
        std::make_tuple(std::array<int, 3>{3, 4, 1}, std::array<bool, 3>{true, true, true}),
        std::make_tuple(std::array<int, 3>{2, 5, 4}, std::array<bool, 3>{true, false, false}),
        std::make_tuple(std::array<int, 3>{6, 3, 5}, std::array<bool, 3>{false, true, false})));

TEST(LinalgAggregation, SingularStaysSingular) {
  const Grid g = box_grid({6, 5, 4}, {true, true, true});
  const Stencil7 fine = diffusion_stencil(g, bed_coefficient(g, 1e3), DirichletSides{});
  ASSERT_TRUE(stencil_is_singular(fine));
  Stencil7 s = fine;
  for (int level = 0; level < 3; ++level) {
    const Aggregation agg = choose_aggregation(s, 0.25);
    Stencil7 coarse(agg.coarse);
    aggregate_coefficients(s, agg, coarse);
    EXPECT_TRUE(stencil_is_singular(coarse)) << level;
    s = coarse;
  }
  EXPECT_EQ(s.grid.cells(), 1u);
}

TEST(LinalgAggregation, SemiCoarsensAlongStrongAxisOnly) {
  // Δ = (1, 1/16, 1/16): a_x = ΔyΔz/Δx = 1/256, a_y = a_z = 1, so x is weak.
  Grid g = box_grid({8, 16, 4}, {true, false, true});
  g.length = {8, 1, 0.25};
  const Stencil7 s = diffusion_stencil(g, std::vector<double>(g.cells(), 1.0),
                                       DirichletSides{false, false, false, true});
  const Aggregation agg = choose_aggregation(s, 0.25);
  EXPECT_EQ(agg.coarse.n[0], 8);  // weak: not coarsened
  EXPECT_EQ(agg.coarse.n[1], 8);
  EXPECT_EQ(agg.coarse.n[2], 2);
}

}  // namespace
}  // namespace gridfree
