// SPDX-License-Identifier: GPL-3.0-or-later
// Plug flow and the analytic-drag pressure profile as the initial guess.
#include "flow/initial_state.h"

#include "flow/probes.h"

namespace gridfree {

double inflow_velocity(const FlowBoundaries& bc) {
  for (const auto& side : bc[1])
    if (side.kind == BoundaryKind::kMassInflow) return side.superficial_velocity_cm_s;
  return 0.0;
}

void warm_start(const FlowProblem& problem, const std::vector<double>& eps_s,
                const DragUpdate& drag, FlowState& state, bool cold) {
  const Grid& g = problem.grid;
  state.eps_g.resize(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) state.eps_g[c] = 1.0 - eps_s[c];
  state.u = make_face_vector(g, 0.0);
  state.p.assign(g.cells(), 0.0);
  state.drag.beta.assign(g.cells(), 0.0);
  update_eps_faces(problem, state);

  // Plug flow: u_y = ±U0/ε̄ (the sign of the inflow side).
  double u0 = 0;
  for (int side = 0; side < 2; ++side)
    if (problem.bc[1][side].kind == BoundaryKind::kMassInflow)
      u0 = side == 0 ? problem.bc[1][0].superficial_velocity_cm_s
                     : -problem.bc[1][1].superficial_velocity_cm_s;
  if (!cold)
    for (std::size_t f = 0; f < state.u[1].size(); ++f) state.u[1][f] = u0 / state.eps_face[1][f];
  apply_fixed_faces(problem, state);
  if (cold) return;

  if (drag) drag(state, state.drag);
  const int top_outlet = problem.bc[1][1].kind == BoundaryKind::kPressureOutflow ? 1
                         : problem.bc[1][0].kind == BoundaryKind::kPressureOutflow ? 0 : -1;
  if (top_outlet < 0) return;

  // Row gradient G_j = ρ g_y − ⟨β U0/ε_g²⟩_j, integrated from the outlet.
  const int ny = g.n[1];
  const double hy = g.h(1);
  std::vector<double> grad(std::size_t(ny), 0.0);
  for (int j = 0; j < ny; ++j) {
    double s = 0;
    for (int k = 0; k < g.n[2]; ++k)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        s += state.drag.beta[c] * u0 / (state.eps_g[c] * state.eps_g[c]);
      }
    grad[std::size_t(j)] = problem.gas.rho * problem.gas.gravity[1] - s / (double(g.n[0]) * g.n[2]);
  }
  std::vector<double> row(std::size_t(ny), 0.0);
  if (top_outlet == 1) {
    double p = problem.bc[1][1].pressure_dyn_cm2;
    for (int j = ny - 1; j >= 0; --j) {
      p -= grad[std::size_t(j)] * hy;
      row[std::size_t(j)] = p;
    }
  } else {
    double p = problem.bc[1][0].pressure_dyn_cm2;
    for (int j = 0; j < ny; ++j) {
      p += grad[std::size_t(j)] * hy;
      row[std::size_t(j)] = p;
    }
  }
  for (std::size_t c = 0; c < g.cells(); ++c) state.p[c] = row[std::size_t(cell_coords(g, c)[1])];
}

}  // namespace gridfree
