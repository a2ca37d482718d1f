// SPDX-License-Identifier: GPL-3.0-or-later
// BiCGSTAB (linalg/bicgstab.h) on non-symmetric convection–diffusion
// systems: manufactured discrete solutions (b = A φ_exact), both
// preconditioners, Péclet numbers from diffusion- to convection-dominated,
// and robustness (zero right-hand side, iteration limit, breakdown-prone
// input never producing NaN).
//
// Tolerance: solves to ||r||/||b|| ≤ 1e-13; these upwind systems are
// M-matrices with cond ≲ 1e3 on the grids used, so the error bound
// cond·1e-13 is far below the 1e-8 asserted.
#include "linalg/bicgstab.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "linalg/model_problems.h"
#include "linalg/stencil_ops.h"
#include "test_grids.h"

namespace gridfree {
namespace {

using test_support::box_grid;

std::vector<double> manufactured_sine(const Grid& g) {
  std::vector<double> phi(g.cells());
  for (std::size_t c = 0; c < phi.size(); ++c) phi[c] = std::sin(0.37 * double(c)) + 0.5;
  return phi;
}

double max_error(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0;
  for (std::size_t c = 0; c < a.size(); ++c) e = std::max(e, std::abs(a[c] - b[c]));
  return e;
}

struct ConvectionDiffusionCase {
  const char* name;
  std::array<int, 3> n;
  std::array<bool, 3> periodic;
  std::array<double, 3> velocity;
  double diffusivity;
  double shift;
};

class LinalgConvectionDiffusion
    : public ::testing::TestWithParam<std::tuple<ConvectionDiffusionCase, GeneralPreconditioner>> {};

TEST_P(LinalgConvectionDiffusion, RecoversManufacturedSolution) {
  const auto& [c, preconditioner] = GetParam();
  const Grid g = box_grid(c.n, c.periodic);
  Stencil7 s = convection_diffusion_stencil(
      g, c.velocity, c.diffusivity, DirichletSides{true, true, true, true, true, true}, c.shift);
  ASSERT_GT(stencil_asymmetry(s), 1e-3) << "the test system must be non-symmetric";
  const std::vector<double> exact = manufactured_sine(g);
  stencil_apply(s, exact, s.b);
  std::vector<double> phi(g.cells(), 0.0);
  GeneralSolverOptions options;
  options.preconditioner = preconditioner;
  const LinearSolveStats stats = solve_general(s, phi, {1e-13, 2000}, options);
  EXPECT_TRUE(stats.converged) << c.name << " " << stats.final_residual;
  EXPECT_LE(stats.final_residual, 1e-13);
  EXPECT_LT(max_error(phi, exact), 1e-8) << c.name;
  std::vector<double> r;
  stencil_residual(s, phi, r);
  double rr = 0, bb = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    rr += r[i] * r[i];
    bb += s.b[i] * s.b[i];
  }
  EXPECT_LE(std::sqrt(rr / bb), 1e-13);
}

INSTANTIATE_TEST_SUITE_P(
    Systems, LinalgConvectionDiffusion,
    ::testing::Combine(
        ::testing::Values(
            ConvectionDiffusionCase{"low_peclet", {10, 10, 10}, {false, false, false}, {1, 0.5, 0.2}, 1.0, 0},
            ConvectionDiffusionCase{"high_peclet", {12, 12, 6}, {false, false, false}, {200, -100, 50}, 1.0, 0},
            ConvectionDiffusionCase{"periodic_xz_momentum_like",
                 {8, 20, 4},
                 {true, false, true},
                 {5, 40, 0},
                 0.1,
                 50.0},
            ConvectionDiffusionCase{"odd_periodic", {7, 13, 5}, {true, true, true}, {30, 10, -20}, 0.5, 1.0}),
        ::testing::Values(GeneralPreconditioner::kGaussSeidel, GeneralPreconditioner::kJacobi)),
    [](const auto& param_info) {
      return std::string(std::get<0>(param_info.param).name) +
             (std::get<1>(param_info.param) == GeneralPreconditioner::kJacobi ? "_jacobi" : "_gs");
    });

TEST(LinalgBicgstab, ZeroRightHandSide) {
  const Grid g = box_grid({5, 5, 5}, {false, false, false});
  const Stencil7 s = convection_diffusion_stencil(
      g, {3, 2, 1}, 1.0, DirichletSides{true, true, true, true, true, true});
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solve_general(s, phi, {});
  EXPECT_TRUE(stats.converged);
  EXPECT_EQ(stats.iterations, 0);
}

TEST(LinalgBicgstab, IterationLimitReported) {
  const Grid g = box_grid({16, 16, 16}, {false, false, false});
  Stencil7 s = convection_diffusion_stencil(g, {100, 50, 0}, 1.0,
                                            DirichletSides{true, true, true, true, true, true});
  stencil_apply(s, manufactured_sine(g), s.b);
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solve_general(s, phi, {1e-14, 2});
  EXPECT_LE(stats.iterations, 2);
  EXPECT_FALSE(stats.converged);
  EXPECT_LT(stats.final_residual, stats.initial_residual);
}

TEST(LinalgBicgstab, NeverReturnsNaN) {
  // A singular, inconsistent system (pure Neumann diffusion, b with a
  // non-zero mean): no solution exists; the solver must stop without NaN.
  const Grid g = box_grid({6, 6, 6}, {true, true, true});
  Stencil7 s = convection_diffusion_stencil(g, {0, 0, 0}, 1.0, DirichletSides{});
  std::fill(s.b.begin(), s.b.end(), 1.0);
  std::vector<double> phi(g.cells(), 0.0);
  const LinearSolveStats stats = solve_general(s, phi, {1e-10, 300});
  EXPECT_FALSE(stats.converged);
  for (double v : phi) ASSERT_TRUE(std::isfinite(v));
  EXPECT_TRUE(std::isfinite(stats.final_residual));
}

}  // namespace
}  // namespace gridfree
