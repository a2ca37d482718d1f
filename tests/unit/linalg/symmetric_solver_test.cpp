// SPDX-License-Identifier: GPL-3.0-or-later
// Conjugate gradients with multigrid and Jacobi preconditioning on
// manufactured discrete problems: pick φ_exact, compute b = A φ_exact with
// the stencil product, solve from φ = 0 and compare with φ_exact.
//
// Tolerance: the solve runs to ||r||/||b|| ≤ 1e-13; the error is then at
// most cond(A)·1e-13 in the worst case, but the residual of these smooth
// manufactured fields is not concentrated in the smallest eigenmodes, and
// the observed errors are ~1e-12 even for the 1e6 coefficient contrast;
// 1e-8 relative to max|φ| leaves margin while still catching any wrong
// answer (a wrong solve is off by O(1)).
#include "linalg/symmetric_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "linalg/model_problems.h"
#include "linalg/stencil_ops.h"
#include "linalg/vector_ops.h"
#include "test_grids.h"

namespace gridfree {
namespace {

using test_support::box_grid;

std::vector<double> manufactured(const Grid& g) {
  std::vector<double> phi(g.cells());
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i)
        phi[g.index(i, j, k)] = std::sin(0.9 * i + 0.3) * std::cos(0.4 * j) + 0.2 * k +
                                0.05 * double((i * 7 + j * 3 + k * 5) % 11);
  return phi;
}

double max_relative_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0, scale = 0;
  for (std::size_t c = 0; c < a.size(); ++c) {
    e = std::max(e, std::abs(a[c] - b[c]));
    scale = std::max(scale, std::abs(b[c]));
  }
  return e / scale;
}

struct ManufacturedCase {
  const char* name;
  std::array<int, 3> n;
  std::array<double, 3> length;
  std::array<bool, 3> periodic;
  DirichletSides dirichlet;
  double contrast;  // κ ratio of the bed field (1 = uniform)
};

std::vector<double> kappa_for(const Grid& g, double contrast) {
  if (contrast == 1) return std::vector<double>(g.cells(), 1.0);
  return bed_coefficient(g, contrast);
}

class LinalgManufacturedSolve
    : public ::testing::TestWithParam<std::tuple<ManufacturedCase, SymmetricPreconditioner>> {};

TEST_P(LinalgManufacturedSolve, RecoversExactSolution) {
  const auto& [c, preconditioner] = GetParam();
  const Grid g = box_grid(c.n, c.length, c.periodic);
  Stencil7 s = diffusion_stencil(g, kappa_for(g, c.contrast), c.dirichlet);
  const std::vector<double> exact = manufactured(g);
  stencil_apply(s, exact, s.b);
  SymmetricSolverOptions options;
  options.preconditioner = preconditioner;
  options.multigrid.coarsest_cells = 8;  // force several levels on small grids
  SymmetricSolver solver(options);
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solver.solve(s, phi, {1e-13, 5000});
  EXPECT_TRUE(stats.converged) << c.name << " residual " << stats.final_residual;
  EXPECT_LE(stats.final_residual, 1e-13);
  EXPECT_FALSE(solver.singular());
  EXPECT_LT(max_relative_error(phi, exact), 1e-8) << c.name;
  if (preconditioner == SymmetricPreconditioner::kMultigrid) {
    EXPECT_GE(solver.level_sizes().size(), 2u) << c.name;
  }
}

constexpr DirichletSides kTopOnly{false, false, false, true, false, false};
constexpr DirichletSides kAll{true, true, true, true, true, true};
constexpr DirichletSides kBottomTop{false, false, true, true, false, false};

INSTANTIATE_TEST_SUITE_P(
    Grids, LinalgManufacturedSolve,
    ::testing::Combine(
        ::testing::Values(
            ManufacturedCase{"periodic_xz_outflow", {8, 16, 4}, {1, 2, 0.5}, {true, false, true}, kTopOnly, 1},
            ManufacturedCase{"all_dirichlet", {9, 9, 9}, {1, 1, 1}, {false, false, false}, kAll, 1},
            ManufacturedCase{"mixed", {6, 10, 7}, {1, 1, 1}, {true, false, false}, kBottomTop, 1},
            ManufacturedCase{"anisotropic_cells", {8, 12, 6}, {4, 1, 0.5}, {true, false, true}, kTopOnly, 1},
            ManufacturedCase{"odd_sizes", {7, 13, 5}, {0.7, 1.3, 0.5}, {true, false, true}, kTopOnly, 1},
            ManufacturedCase{"one_cell_z", {9, 15, 1}, {1, 2, 0.1}, {true, false, true}, kTopOnly, 1},
            ManufacturedCase{"bed_contrast_1e3", {10, 30, 6}, {3, 20, 1}, {true, false, true}, kTopOnly, 1e3},
            ManufacturedCase{"odd_periodic_bed", {7, 21, 3}, {3, 20, 1}, {true, false, true}, kTopOnly, 1e2},
            ManufacturedCase{"aspect_ratio_10", {10, 20, 8}, {10, 2, 8}, {true, false, true}, kTopOnly, 1},
            ManufacturedCase{"bed_contrast_1e6", {12, 40, 4}, {3, 20, 1}, {true, false, true}, kTopOnly, 1e6}),
        ::testing::Values(SymmetricPreconditioner::kMultigrid, SymmetricPreconditioner::kJacobi)),
    [](const auto& param_info) {
      return std::string(std::get<0>(param_info.param).name) +
             (std::get<1>(param_info.param) == SymmetricPreconditioner::kMultigrid ? "_mg"
                                                                                   : "_jacobi");
    });

// Fully periodic, no Dirichlet anywhere: A·1 = 0, solved in the zero-mean sense.
class LinalgSingularSolve : public ::testing::TestWithParam<SymmetricPreconditioner> {};

TEST_P(LinalgSingularSolve, ZeroMeanSolution) {
  const Grid g = box_grid({7, 13, 5}, {1, 2, 1}, {true, true, true});
  Stencil7 s = diffusion_stencil(g, bed_coefficient(g, 100), DirichletSides{});
  std::vector<double> exact = manufactured(g);
  remove_mean(exact);
  stencil_apply(s, exact, s.b);
  // An inconsistent constant in b must be projected out, not fought.
  for (double& v : s.b) v += 0.3;
  SymmetricSolverOptions options;
  options.preconditioner = GetParam();
  options.multigrid.coarsest_cells = 20;
  SymmetricSolver solver(options);
  std::vector<double> phi(g.cells(), 1.0);  // initial guess with a non-zero mean
  const LinearSolveStats stats = solver.solve(s, phi, {1e-12, 5000});
  EXPECT_TRUE(solver.singular());
  EXPECT_TRUE(stats.converged) << stats.final_residual;
  // Mean of φ is removed: round-off of a sum of ~455 O(1) values.
  EXPECT_NEAR(sum(phi) / double(phi.size()), 0.0, 1e-13);
  EXPECT_LT(max_relative_error(phi, exact), 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Preconditioners, LinalgSingularSolve,
                         ::testing::Values(SymmetricPreconditioner::kMultigrid,
                                           SymmetricPreconditioner::kJacobi));

TEST(LinalgSymmetricSolver, ZeroRightHandSideGivesZero) {
  const Grid g = box_grid({4, 4, 4}, {1, 1, 1}, {false, false, false});
  const Stencil7 s = diffusion_stencil(g, std::vector<double>(g.cells(), 1.0), kAll);
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solve_symmetric(s, phi, {});
  EXPECT_TRUE(stats.converged);
  EXPECT_EQ(stats.iterations, 0);
  for (double v : phi) EXPECT_EQ(v, 0.0);
}

TEST(LinalgSymmetricSolver, ResetupWithNewCoefficientsReusesHierarchy) {
  const Grid g = box_grid({12, 24, 6}, {1, 2, 0.5}, {true, false, true});
  SymmetricSolverOptions options;
  options.multigrid.coarsest_cells = 30;
  SymmetricSolver solver(options);
  const std::vector<double> exact = manufactured(g);
  for (double contrast : {1.0, 10.0, 1000.0}) {
    Stencil7 s = diffusion_stencil(g, kappa_for(g, contrast), kTopOnly, 0.0);
    stencil_apply(s, exact, s.b);
    std::vector<double> phi(g.cells(), 0.0);
    const LinearSolveStats stats = solver.solve(s, phi, {1e-12, 500});
    EXPECT_TRUE(stats.converged) << contrast;
    EXPECT_LT(max_relative_error(phi, exact), 1e-8) << contrast;
  }
  // Then a different grid with the same solver object.
  const Grid g2 = box_grid({7, 13, 5}, {0.7, 1.3, 0.5}, {true, false, true});
  Stencil7 s2 = diffusion_stencil(g2, bed_coefficient(g2, 1e2), kTopOnly);
  const std::vector<double> exact2 = manufactured(g2);
  stencil_apply(s2, exact2, s2.b);
  std::vector<double> phi2(g2.cells(), 0.0);
  EXPECT_TRUE(solver.solve(s2, phi2, {1e-12, 500}).converged);
  EXPECT_LT(max_relative_error(phi2, exact2), 1e-8);
}

TEST(LinalgSymmetricSolver, FreeFunctionMatchesClassAndReportsStatistics) {
  const Grid g = box_grid({16, 32, 8}, {1, 2, 0.5}, {true, false, true});
  Stencil7 s = diffusion_stencil(g, bed_coefficient(g, 1e3), kTopOnly);
  stencil_apply(s, manufactured(g), s.b);
  std::vector<double> a(g.cells(), 0.0), b(g.cells(), 0.0);
  const LinearSolveStats sa = solve_symmetric(s, a, {1e-8, 500});
  SymmetricSolver solver;
  const LinearSolveStats sb = solver.solve(s, b, {1e-8, 500});
  EXPECT_EQ(sa.iterations, sb.iterations);
  EXPECT_EQ(a, b);
  EXPECT_NEAR(sa.initial_residual, 1.0, 1e-12);  // φ0 = 0 → r0 = b
  EXPECT_LE(sa.final_residual, 1e-8);
  EXPECT_GT(sa.iterations, 0);
  // Check the reported residual against an independent evaluation.
  std::vector<double> r;
  stencil_residual(s, a, r);
  EXPECT_NEAR(norm2(r) / norm2(s.b), sa.final_residual, 1e-3 * sa.final_residual);
}

TEST(LinalgSymmetricSolver, HitsIterationLimitWithoutClaimingConvergence) {
  const Grid g = box_grid({16, 32, 8}, {1, 2, 0.5}, {true, false, true});
  Stencil7 s = diffusion_stencil(g, bed_coefficient(g, 1e3), kTopOnly);
  stencil_apply(s, manufactured(g), s.b);
  SymmetricSolverOptions options;
  options.preconditioner = SymmetricPreconditioner::kJacobi;
  SymmetricSolver solver(options);
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solver.solve(s, phi, {1e-12, 3});
  EXPECT_EQ(stats.iterations, 3);
  EXPECT_FALSE(stats.converged);
  EXPECT_GT(stats.final_residual, 1e-12);
}

TEST(LinalgSymmetricSolver, RejectsInvalidStencil) {
  const Grid g = box_grid({4, 4, 4}, {1, 1, 1}, {false, false, false});
  Stencil7 s = diffusion_stencil(g, std::vector<double>(g.cells(), 1.0), kAll);
  s.an[g.index(1, 3, 1)] = 2.0;  // across the non-periodic y-high side
  std::vector<double> phi(g.cells(), 0.0);
  EXPECT_THROW(solve_symmetric(s, phi, {}), std::invalid_argument);
}

}  // namespace
}  // namespace gridfree
