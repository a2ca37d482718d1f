// SPDX-License-Identifier: GPL-3.0-or-later
// One SIMPLEC sweep with the drag fixed (simplec_sweep.h).
#include "flow/simplec_sweep.h"

#include <algorithm>
#include <chrono>

#include "flow/mass_flux.h"
#include "flow/pressure_correction.h"
#include "flow/residuals.h"
#include "flow/phase_clock.h"

namespace gridfree {
namespace {

// The face grid of the component with the most faces.
Grid largest_face_grid(const Grid& g) {
  int best = 0;
  for (int a = 1; a < 3; ++a)
    if (FaceLayout(g, a).size() > FaceLayout(g, best).size()) best = a;
  return FaceLayout(g, best).as_grid(g);
}

// Exactly `iterations` inner iterations (no tolerance test).
LinearSolverSettings replayed(int iterations) { return {0.0, iterations}; }

}  // namespace

SweepWorkspace::SweepWorkspace(const Grid& g) : momentum(largest_face_grid(g)) {}

SweepReport simplec_sweep(const FlowProblem& problem, const SimpleSettings& settings, FlowState& state,
                          SweepWorkspace& ws, PhaseSeconds* seconds, const SweepCounts* replay) {
  const Grid& g = problem.grid;
  SweepReport report;
  PhaseClock clock;
  // Momentum predictor: u* for each component with lagged mass fluxes.
  compute_mass_fluxes(problem, state, ws.mass_flux);
  double momentum_residual = 0, momentum_scale = 0;
  {
    const CellField divergence = velocity_divergence(g, state.u);
    for (int a = 0; a < 3; ++a) {
      MomentumSystem& sys = ws.momentum;
      reshape_stencil(sys.eq, FaceLayout(g, a).as_grid(g));
      assemble_momentum(problem, state, ws.mass_flux, divergence, a, settings.relax_u, sys, ws.d[a], ws.relaxed_correction.get());
      momentum_residual += sys.residual;
      momentum_scale += sys.scale;
      // Inexact solve: reduce this component's residual ||r||/||b|| 10×
      // (clamped to [linear_floor, momentum_tolerance]).
      LinearSolverSettings solver{settings.momentum_tolerance, settings.linear_max_iterations};
      solver.tolerance = std::clamp(0.1 * normalized(sys.residual_l2, sys.rhs_l2), settings.linear_floor,
                                    settings.momentum_tolerance);
      if (replay) solver = replayed(replay->momentum[std::size_t(a)]);
      const LinearSolveStats st = solve_general(sys.eq, state.u[a].values, solver);
      report.momentum_iterations += st.iterations;
      report.counts.momentum[std::size_t(a)] = st.iterations;
      if (!st.converged && !replay) report.linear_failures = true;
    }
  }  // ∇·u is freed here
  if (seconds) clock.charge(seconds->momentum);

  // Pressure correction: p ← p + α_p p', u ← u* + d ∇p'. Its multigrid
  // hierarchy is rebuilt for new coefficients every sweep anyway, so it
  // lives only for this step.
  const double continuity_scale = continuity_reference(ws.mass_flux);
  reshape_stencil(ws.momentum.eq, g);
  PressureCorrectionResult pc;
  {
    SymmetricSolver pressure_linear_solver;
    std::vector<double> p_prime;
    const LinearSolverSettings pressure_solver =
        replay ? replayed(replay->pressure)
               : LinearSolverSettings{settings.pressure_tolerance, settings.linear_max_iterations};
    pc = correct_pressure(problem, state, ws.d, settings.relax_p, pressure_solver, ws.momentum.eq,
                          pressure_linear_solver, p_prime, ws.mass_flux);
  }
  report.pressure_iterations = pc.solve.iterations;
  report.counts.pressure = pc.solve.iterations;
  if (!pc.solve.converged && !replay) report.linear_failures = true;
  if (seconds) clock.charge(seconds->pressure);

  report.continuity = normalized(pc.imbalance, continuity_scale);
  report.momentum = normalized(momentum_residual, momentum_scale);
  return report;
}

}  // namespace gridfree
