// SPDX-License-Identifier: GPL-3.0-or-later
// Linear-solver scaling benchmark: iterations and time against the number of
// unknowns for the symmetric solver (CG + aggregation multigrid vs CG +
// Jacobi) on two pressure-correction-like problems, and for BiCGSTAB on a
// momentum-like convection–diffusion system:
//
//   poisson  κ = 1
//   bed      κ = 1e-3 in a dense bed (lowest 14 % of y) with a bubble, 1 above
//
// on grids 30s × 200s × 10s (s = 1, 2, 4: 60 k, 480 k, 3.84 M cells), cubic
// cells, periodic x and z, Dirichlet only at y-high (the pressure outflow),
// zero flux at y-low. Right-hand side: a smooth field; φ0 = 0; tolerance
// ||r||/||b|| ≤ 1e-8. Each case runs `--repeats` times; the table shows
// medians. Usage:
//   linalg_bench [--scales 1,2,4] [--repeats 3] [--jacobi-max-scale 2] [--threads N]
#include <omp.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "linalg/bicgstab.h"
#include "linalg/model_problems.h"
#include "linalg/symmetric_solver.h"

namespace {

using gridfree::DirichletSides;
using gridfree::Grid;
using gridfree::Stencil7;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

Grid bench_grid(int scale) {
  Grid g;
  g.n = {30 * scale, 200 * scale, 10 * scale};
  g.length = {0.3, 2.0, 0.1};
  g.periodic = {true, false, true};
  return g;
}

void smooth_rhs(const Grid& g, std::vector<double>& b) {
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const double x = g.centre(0, i) / g.length[0], y = g.centre(1, j) / g.length[1];
        const double z = g.centre(2, k) / g.length[2];
        b[g.index(i, j, k)] = g.cell_volume() * (std::sin(6.283 * x) * std::cos(3.1 * y) +
                                                 0.5 * std::cos(6.283 * z) + y);
      }
}

struct Row {
  std::string problem, grid, solver;
  std::size_t cells = 0;
  int levels = 0, iterations = 0;
  bool converged = false;
  double setup = 0, solve = 0;
};

void print(const Row& r) {
  const double per_unknown = 1e6 * (r.setup + r.solve) / double(r.cells);
  std::printf("%-8s %-12s %9zu %-10s %6d %6d%s %9.3f %9.3f %10.3f %10.4f\n", r.problem.c_str(),
              r.grid.c_str(), r.cells, r.solver.c_str(), r.levels, r.iterations,
              r.converged ? " " : "*", r.setup, r.solve, per_unknown,
              per_unknown / std::max(1, r.iterations));
  std::fflush(stdout);
}

Row run_symmetric(const Stencil7& s, gridfree::SymmetricPreconditioner p,
                  const gridfree::MultigridOptions& mg, int repeats) {
  Row row;
  row.cells = s.grid.cells();
  std::vector<double> setups, solves;
  for (int rep = 0; rep < repeats; ++rep) {
    gridfree::SymmetricSolverOptions options;
    options.preconditioner = p;
    options.multigrid = mg;
    gridfree::SymmetricSolver solver(options);
    std::vector<double> phi(s.grid.cells(), 0.0);
    auto t0 = Clock::now();
    solver.setup(s);
    setups.push_back(seconds_since(t0));
    t0 = Clock::now();
    const gridfree::LinearSolveStats st = solver.solve(phi, {1e-8, 100000});
    solves.push_back(seconds_since(t0));
    row.iterations = st.iterations;
    row.converged = st.converged;
    row.levels = int(solver.level_sizes().size());
  }
  row.setup = median(setups);
  row.solve = median(solves);
  return row;
}

Row run_general(const Stencil7& s, int repeats) {
  Row row;
  row.cells = s.grid.cells();
  std::vector<double> solves;
  for (int rep = 0; rep < repeats; ++rep) {
    std::vector<double> phi(s.grid.cells(), 0.0);
    const auto t0 = Clock::now();
    const gridfree::LinearSolveStats st = gridfree::solve_general(s, phi, {1e-8, 10000});
    solves.push_back(seconds_since(t0));
    row.iterations = st.iterations;
    row.converged = st.converged;
  }
  row.solve = median(solves);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"gridfree linear-solver scaling benchmark"};
  std::vector<int> scales{1, 2, 4};
  int repeats = 3, jacobi_max_scale = 2, threads = 0;
  gridfree::MultigridOptions mg;
  std::string only;
  app.add_option("--scales", scales, "grid scale factors s (grid 30s x 200s x 10s)")
      ->delimiter(',');
  app.add_option("--repeats", repeats, "runs per case (median reported)");
  app.add_option("--jacobi-max-scale", jacobi_max_scale, "largest s for Jacobi-PCG");
  app.add_option("--threads", threads, "OpenMP threads (default: OpenMP's choice)");
  app.add_option("--omega", mg.coarse_correction_scale, "multigrid coarse-correction scale");
  app.add_option("--sweeps", mg.smoothing_sweeps, "multigrid smoothing sweeps");
  app.add_option("--coarsest", mg.coarsest_cells, "multigrid coarsest-level size");
  app.add_option("--only", only, "run only this problem (poisson, bed, momentum)");
  CLI11_PARSE(app, argc, argv);
  if (threads > 0) omp_set_num_threads(threads);

  std::printf("threads %d, tolerance 1e-8, medians of %d runs; * = not converged\n",
              omp_get_max_threads(), repeats);
  std::printf("%-8s %-12s %9s %-10s %6s %6s  %9s %9s %10s %10s\n", "problem", "grid", "cells",
              "solver", "levels", "iters", "setup_s", "solve_s", "us/unknown", "us/unk/it");
  const DirichletSides outflow{false, false, false, true, false, false};
  for (int scale : scales) {
    const Grid g = bench_grid(scale);
    const std::string name = std::to_string(g.n[0]) + "x" + std::to_string(g.n[1]) + "x" +
                             std::to_string(g.n[2]);
    for (const char* problem : {"poisson", "bed"}) {
      if (!only.empty() && only != problem) continue;
      const double contrast = std::string(problem) == "bed" ? 1e3 : 1.0;
      Stencil7 s = gridfree::diffusion_stencil(
          g, contrast == 1 ? std::vector<double>(g.cells(), 1.0)
                           : gridfree::bed_coefficient(g, contrast),
          outflow);
      smooth_rhs(g, s.b);
      Row amg = run_symmetric(s, gridfree::SymmetricPreconditioner::kMultigrid, mg, repeats);
      amg.problem = problem, amg.grid = name, amg.solver = "cg+amg";
      print(amg);
      if (scale <= jacobi_max_scale) {
        Row jac = run_symmetric(s, gridfree::SymmetricPreconditioner::kJacobi, mg,
                                scale >= 4 ? 1 : repeats);
        jac.problem = problem, jac.grid = name, jac.solver = "cg+jacobi";
        print(jac);
      }
    }
    if (!only.empty() && only != "momentum") continue;
    // Momentum-like: upwind convection at cell Péclet ~ 2 plus a drag/relaxation
    // diagonal of the same order as the convective coefficients.
    const double h = g.h(1);
    Stencil7 m = gridfree::convection_diffusion_stencil(g, {0.5, 2.0, 0.0}, h, outflow,
                                                        2.0 / h);
    smooth_rhs(g, m.b);
    Row bi = run_general(m, repeats);
    bi.problem = "momentum", bi.grid = name, bi.solver = "bicgstab";
    print(bi);
  }
  return 0;
}
