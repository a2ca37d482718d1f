// SPDX-License-Identifier: GPL-3.0-or-later
// Assembly and solution of the pressure-correction equation (see the header).
#include "flow/pressure_correction.h"

#include <cmath>

#include "flow/mass_flux.h"
#include "flow/parallel.h"

namespace gridfree {

PressureCorrectionResult correct_pressure(const FlowProblem& problem, FlowState& state,
                                          const FaceVector& d, double relax_p,
                                          const LinearSolverSettings& settings, Stencil7& eq,
                                          SymmetricSolver& solver, std::vector<double>& p_prime,
                                          FaceVector& flux) {
  const Grid& g = problem.grid;
  const double rho = problem.gas.rho;
  compute_mass_fluxes(problem, state, flux);
  auto nb = neighbour_arrays(eq);
  const long cells = static_cast<long>(g.cells());
  const bool has_outlet = has_pressure_outlet(problem.bc);

#pragma omp parallel for schedule(static) if (cells > kMinParallel)
  for (long cl = 0; cl < cells; ++cl) {
    const std::size_t c = std::size_t(cl);
    const std::array<int, 3> x = cell_coords(g, c);
    double ap = 0;
    for (int a = 0; a < 3; ++a) {
      const FaceLayout& lay = d[a].layout;
      const double area = g.face_area(a);
      for (int side = 0; side < 2; ++side) {
        std::array<int, 3> xf = x;
        if (side == 1) xf[a] = (g.periodic[a] && x[a] + 1 == g.n[a]) ? 0 : x[a] + 1;
        const std::size_t f = lay.index(xf);
        const double coeff = rho * state.eps_face[a][f] * area * d[a][f];
        double link = 0;
        if (g.periodic[a]) {
          link = g.n[a] > 1 ? coeff : 0.0;  // one periodic cell: p'_L = p'_R
        } else {
          const FaceRole role = face_role(g, problem.bc, a, xf[a]);
          if (role == FaceRole::kInterior) link = coeff;
          else if (role == FaceRole::kOutflow) ap += coeff;  // ghost p' = 0
        }
        (*nb[a][side])[c] = link;
        ap += link;
      }
    }
    eq.ap[c] = ap;
    eq.b[c] = -cell_mass_imbalance(problem, flux, c);
  }
  PressureCorrectionResult result;
  result.imbalance = deterministic_sum(g.cells(), [&](std::size_t c) { return std::abs(eq.b[c]); });

  if (!has_outlet) {
    // Singular (Neumann) system: make the right-hand side consistent and
    // shift the diagonal by a round-off-sized amount; the mean is reset below.
    const double mean_b = deterministic_sum(g.cells(), [&](std::size_t c) { return eq.b[c]; }) /
                          double(g.cells());
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
    for (long c = 0; c < cells; ++c) {
      eq.b[std::size_t(c)] -= mean_b;
      eq.ap[std::size_t(c)] *= 1.0 + 1e-12;
    }
  }

  p_prime.assign(g.cells(), 0.0);
  if (result.imbalance > 0) result.solve = solver.solve(eq, p_prime, settings);
  else result.solve.converged = true;

  // p ← p + α_p p'.
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
  for (long c = 0; c < cells; ++c) state.p[std::size_t(c)] += relax_p * p_prime[std::size_t(c)];
  if (!has_outlet) {
    const double mean_p = deterministic_sum(g.cells(), [&](std::size_t c) { return state.p[c]; }) /
                          double(g.cells());
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
    for (long c = 0; c < cells; ++c) state.p[std::size_t(c)] -= mean_p;
  }

  // u ← u* + d (p'_L − p'_R).
  for (int a = 0; a < 3; ++a) {
    const FaceLayout& lay = d[a].layout;
    const long faces = static_cast<long>(lay.size());
#pragma omp parallel for schedule(static) if (faces > kMinParallel)
    for (long fl = 0; fl < faces; ++fl) {
      const std::size_t f = std::size_t(fl);
      if (d[a][f] == 0.0) continue;
      std::array<int, 3> x = face_coords(lay, f);
      const int fa = x[a];
      double pl = 0, pr = 0;  // ghost p' = 0 beyond an outflow
      if (g.periodic[a] || fa < g.n[a]) pr = p_prime[g.index(x[0], x[1], x[2])];
      if (g.periodic[a] || fa > 0) {
        x[a] = fa == 0 ? g.n[a] - 1 : fa - 1;
        pl = p_prime[g.index(x[0], x[1], x[2])];
      }
      state.u[a][f] += d[a][f] * (pl - pr);
    }
  }
  return result;
}

}  // namespace gridfree
