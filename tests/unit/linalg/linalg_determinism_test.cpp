// SPDX-License-Identifier: GPL-3.0-or-later
// Results must not depend on the OpenMP thread count: every reduction is
// fixed-order (vector_ops.h) and every parallel loop writes disjoint
// entries, so 1 and 2 threads must give bitwise identical solutions and
// statistics. The grid is large enough (> 20,000 cells) for the loops to
// actually run in parallel and to span several reduction blocks; a few
// iterations suffice (the unit label must stay fast on a loaded machine).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "linalg/bicgstab.h"
#include "linalg/model_problems.h"
#include "linalg/stencil_ops.h"
#include "linalg/symmetric_solver.h"
#include "linalg/vector_ops.h"

namespace gridfree {
namespace {

Grid bed_grid() {
  Grid g;
  g.n = {15, 100, 15};  // odd periodic axes exercise the Jacobi-style colour path
  g.length = {0.3, 2.0, 0.3};
  g.periodic = {true, false, true};
  return g;
}

struct Outcome {
  std::vector<double> phi;
  LinearSolveStats stats;
};

template <class Solve>
std::vector<Outcome> run_with_threads(Solve solve) {
  const int saved = omp_get_max_threads();
  std::vector<Outcome> out;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    out.push_back(solve());
  }
  omp_set_num_threads(saved);
  return out;
}

void expect_identical(const std::vector<Outcome>& o) {
  for (std::size_t t = 1; t < o.size(); ++t) {
    EXPECT_EQ(o[t].stats.iterations, o[0].stats.iterations);
    EXPECT_EQ(o[t].stats.final_residual, o[0].stats.final_residual);
    EXPECT_TRUE(o[t].phi == o[0].phi) << "threads differ at run " << t;
  }
}

TEST(LinalgDeterminism, DotIsBitwiseIndependentOfThreads) {
  std::vector<double> a(100003), b(100003);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = std::sin(0.1 * double(i)) * 1e3;
    b[i] = std::cos(0.7 * double(i)) / 3;
  }
  const auto results = run_with_threads([&] {
    return Outcome{{dot(a, b), sum(a), norm2(b)}, {}};
  });
  expect_identical(results);
}

TEST(LinalgDeterminism, MultigridCgIndependentOfThreads) {
  const Grid g = bed_grid();
  Stencil7 s = diffusion_stencil(g, bed_coefficient(g, 1e3),
                                 DirichletSides{false, false, false, true, false, false});
  for (std::size_t c = 0; c < s.b.size(); ++c) s.b[c] = std::sin(0.01 * double(c));
  expect_identical(run_with_threads([&] {
    std::vector<double> phi(g.cells(), 0.0);
    const LinearSolveStats st = solve_symmetric(s, phi, {1e-12, 3});
    return Outcome{phi, st};
  }));
}

TEST(LinalgDeterminism, SingularJacobiCgIndependentOfThreads) {
  Grid g = bed_grid();
  g.periodic = {true, true, true};
  Stencil7 s = diffusion_stencil(g, bed_coefficient(g, 10), DirichletSides{});
  for (std::size_t c = 0; c < s.b.size(); ++c) s.b[c] = std::cos(0.003 * double(c));
  SymmetricSolverOptions options;
  options.preconditioner = SymmetricPreconditioner::kJacobi;
  expect_identical(run_with_threads([&] {
    SymmetricSolver solver(options);
    std::vector<double> phi(g.cells(), 0.0);
    // Not run to convergence: identical iterates are the point.
    const LinearSolveStats st = solver.solve(s, phi, {1e-12, 10});
    return Outcome{phi, st};
  }));
}

TEST(LinalgDeterminism, BicgstabIndependentOfThreads) {
  const Grid g = bed_grid();
  Stencil7 s = convection_diffusion_stencil(g, {1, 20, -3}, 0.01,
                                            DirichletSides{false, false, true, true, false, false},
                                            10.0);
  for (std::size_t c = 0; c < s.b.size(); ++c) s.b[c] = std::sin(0.02 * double(c));
  expect_identical(run_with_threads([&] {
    std::vector<double> phi(g.cells(), 0.0);
    const LinearSolveStats st = solve_general(s, phi, {1e-12, 8});
    return Outcome{phi, st};
  }));
}

}  // namespace
}  // namespace gridfree
