// The SIMPLEC outer loop (simple_loop.h): a handful of named steps.
#include "flow/simple_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>
#include <sstream>

#include "flow/anderson.h"
#include "flow/iterative_error.h"
#include "flow/mass_flux.h"
#include "flow/momentum.h"
#include "flow/pressure_correction.h"
#include "flow/residuals.h"

namespace gridfree {
namespace {

bool finite(double x) { return std::isfinite(x); }

std::string format_number(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// The face grid of the component with the most faces.
Grid largest_face_grid(const Grid& g) {
  int best = 0;
  for (int a = 1; a < 3; ++a)
    if (FaceLayout(g, a).size() > FaceLayout(g, best).size()) best = a;
  return FaceLayout(g, best).as_grid(g);
}

// Everything the loop keeps across outer iterations. The work of one phase
// (the linear solvers' vectors, the pressure multigrid hierarchy, p') is
// allocated in that phase and freed at its end, so the phases share memory
// instead of each holding its own (docs/SOLVER.md "Memory").
struct Workspace {
  explicit Workspace(const Grid& g) : momentum(largest_face_grid(g)) {}
  // One system for the three momentum components in turn (each is
  // assembled and solved before the next), whose stencil then holds the
  // pressure correction (assembled afresh each iteration): a quarter of the
  // memory of four systems.
  MomentumSystem momentum;
  // F of the iterate entering the iteration (the momentum assembly's lagged
  // fluxes); the pressure correction then overwrites it with F of u*.
  FaceVector mass_flux;
  FaceVector d;  // SIMPLEC coefficients
};

// Adds the seconds since the last call (or construction) to a total.
class PhaseClock {
 public:
  void charge(double& total) {
    const auto now = std::chrono::steady_clock::now();
    total += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

SimpleOutcome run_simple(const FlowProblem& problem, const SimpleSettings& settings,
                         FlowState& state, const DragUpdate& drag,
                         const QuantityOfInterest& qoi, const IterationCallback& on_iteration,
                         const LoopControl& control) {
  const Grid& g = problem.grid;
  auto ws = std::make_unique<Workspace>(g);
  update_eps_faces(problem, state);
  apply_fixed_faces(problem, state);
  if (state.drag.beta.empty()) state.drag.beta.assign(g.cells(), 0.0);

  SimpleOutcome out;
  std::deque<double> qoi_history;
  double first_continuity = -1, first_momentum = -1;
  const LinearSolverSettings momentum_solver{settings.momentum_tolerance, settings.linear_max_iterations};
  const LinearSolverSettings pressure_solver{settings.pressure_tolerance, settings.linear_max_iterations};
  std::unique_ptr<AndersonMixer> mixer;
  std::vector<double> x_entering;
  if (settings.anderson_depth > 0) mixer = std::make_unique<AndersonMixer>(settings.anderson_depth);

  int first_iteration = 1;
  if (control.resume) {
    first_iteration = control.resume->iteration + 1;
    qoi_history.assign(control.resume->qoi_history.begin(), control.resume->qoi_history.end());
    first_continuity = control.resume->first_continuity;
    first_momentum = control.resume->first_momentum;
  }

  for (int it = first_iteration; it <= settings.max_iterations; ++it) {
    IterationReport report;
    report.iteration = it;

    PhaseClock clock;
    // 1. Drag from the current velocity field.
    const bool drag_fresh = !drag || (it - 1) % std::max(1, settings.drag_interval) == 0;
    if (drag && drag_fresh) drag(state, state.drag);
    clock.charge(out.seconds.drag);

    if (mixer) AndersonMixer::pack(state.u, state.p, x_entering);
    // 2. Momentum predictor: u* for each component with lagged mass fluxes.
    compute_mass_fluxes(problem, state, ws->mass_flux);
    double momentum_residual = 0, momentum_scale = 0;
    {
      const CellField divergence = velocity_divergence(g, state.u);
      for (int a = 0; a < 3; ++a) {
        MomentumSystem& sys = ws->momentum;
        reshape_stencil(sys.eq, FaceLayout(g, a).as_grid(g));
        assemble_momentum(problem, state, ws->mass_flux, divergence, a, settings.relax_u, sys, ws->d[a]);
        momentum_residual += sys.residual;
        momentum_scale += sys.scale;
        // Inexact solve: reduce this component's residual ||r||/||b|| 10×
        // (clamped to [linear_floor, momentum_tolerance]).
        LinearSolverSettings solver = momentum_solver;
        solver.tolerance = std::clamp(0.1 * normalized(sys.residual_l2, sys.rhs_l2), settings.linear_floor,
                                      settings.momentum_tolerance);
        const LinearSolveStats st = solve_general(sys.eq, state.u[a].values, solver);
        report.momentum_iterations += st.iterations;
        if (!st.converged) out.linear_failures = true;
      }
    }  // ∇·u is freed here
    clock.charge(out.seconds.momentum);

    // 3. Pressure correction: p ← p + α_p p', u ← u* + d ∇p'. Its multigrid
    // hierarchy is rebuilt for new coefficients every iteration anyway, so
    // it lives only for this step.
    const double continuity_scale = continuity_reference(ws->mass_flux);
    reshape_stencil(ws->momentum.eq, g);
    PressureCorrectionResult pc;
    {
      SymmetricSolver pressure_linear_solver;
      std::vector<double> p_prime;
      pc = correct_pressure(problem, state, ws->d, settings.relax_p, pressure_solver, ws->momentum.eq,
                            pressure_linear_solver, p_prime, ws->mass_flux);
    }
    report.pressure_iterations = pc.solve.iterations;
    if (mixer) mixer->mix(x_entering, state.u, state.p);
    if (!pc.solve.converged) out.linear_failures = true;
    clock.charge(out.seconds.pressure);

    // 4. Monitor: residuals, quantity of interest, status.
    report.continuity = normalized(pc.imbalance, continuity_scale);
    report.momentum = normalized(momentum_residual, momentum_scale);
    if (qoi) {
      report.qoi = qoi(state);
      qoi_history.push_back(*report.qoi);
      if (static_cast<int>(qoi_history.size()) > 2 * settings.qoi_window + 1) qoi_history.pop_front();
      const std::size_t back = std::min(qoi_history.size() - 1, std::size_t(settings.qoi_window));
      const double oldest = qoi_history[qoi_history.size() - 1 - back];
      report.qoi_change = qoi_history.size() > 1
                              ? normalized(std::abs(*report.qoi - oldest), std::abs(*report.qoi))
                              : 1.0;
      if (static_cast<int>(qoi_history.size()) <= settings.qoi_window) report.qoi_change = std::max(report.qoi_change, 1.0);
    }
    if (it <= 5) {  // blow-up reference: the early residuals (at least 1e-2)
      first_continuity = std::max({first_continuity, report.continuity, 1e-2});
      first_momentum = std::max({first_momentum, report.momentum, 1e-2});
    }
    out.iterations = it;
    out.continuity = report.continuity;
    out.momentum = report.momentum;
    out.qoi = report.qoi;
    out.qoi_change = report.qoi_change;
    if (qoi) out.qoi_iterative_error = geometric_iterative_error(qoi_history, settings.qoi_window);
    if (on_iteration) on_iteration(report);

    const bool bad = !finite(report.continuity) || !finite(report.momentum) ||
                     (report.qoi && !finite(*report.qoi));
    if (bad || report.continuity > settings.blowup * first_continuity ||
        report.momentum > settings.blowup * first_momentum) {
      out.status = SolveStatus::kDiverged;
      out.reason = "diverged at iteration " + std::to_string(it) + ": continuity residual " +
                   format_number(report.continuity) + ", momentum residual " + format_number(report.momentum);
      out.qoi.reset();
      return out;
    }
    const double tol = settings.steady_tolerance;
    // Steady only in an iteration that updated the drag: its β comes from
    // the iterate it started from, as with an update every iteration.
    if (it >= settings.min_iterations && drag_fresh && report.continuity < tol && report.momentum < tol &&
        (!qoi || report.qoi_change < tol)) {
      out.status = SolveStatus::kConverged;
      return out;
    }
    if (control.stop_requested && control.stop_requested()) {
      if (control.on_stop)
        control.on_stop(state, LoopCounters{it, {qoi_history.begin(), qoi_history.end()}, first_continuity,
                                            first_momentum});
      out.stopped = true;
      return out;
    }
  }
  out.status = SolveStatus::kNotConverged;
  out.reason = "not converged after " + std::to_string(settings.max_iterations) +
               " iterations: continuity residual " + format_number(out.continuity) +
               ", momentum residual " + format_number(out.momentum) +
               ", relative change of the quantity of interest " + format_number(out.qoi_change) +
               " (tolerance " + format_number(settings.steady_tolerance) + ")";
  return out;
}

}  // namespace gridfree
