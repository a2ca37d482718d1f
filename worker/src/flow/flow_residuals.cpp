// SPDX-License-Identifier: GPL-3.0-or-later
// Residual fields of the momentum and continuity equations (flow_residuals.h).
#include "flow/flow_residuals.h"

#include "flow/mass_flux.h"
#include "flow/momentum.h"
#include "linalg/stencil.h"

namespace gridfree {

FaceVector momentum_residuals(const FlowProblem& problem, const FlowState& state) {
  const Grid& g = problem.grid;
  FaceVector flux, d = make_face_vector(g), r = make_face_vector(g);
  compute_mass_fluxes(problem, state, flux);
  const CellField divergence = velocity_divergence(g, state.u);
  for (int a = 0; a < 3; ++a) {
    MomentumSystem sys(FaceLayout(g, a).as_grid(g));
    assemble_momentum(problem, state, flux, divergence, a, 1.0, sys, d[a]);
    stencil_residual(sys.eq, state.u[a].values, r[a].values);
  }
  return r;
}

CellField continuity_residuals(const FlowProblem& problem, const FlowState& state) {
  FaceVector flux;
  compute_mass_fluxes(problem, state, flux);
  CellField c(problem.grid.cells());
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = -cell_mass_imbalance(problem, flux, i);
  return c;
}

}  // namespace gridfree
