// SPDX-License-Identifier: GPL-3.0-or-later
// SIMPLEC outer iterations to a steady state.
//
// One outer iteration:
//   1. drag      β, βv̄ from the current velocity (every `drag_interval`)
//   2. momentum  assemble and solve each component for u* (BiCGSTAB)
//   3. pressure  solve the pressure correction, correct p and u (CG + MG)
//   4. monitor   normalized residuals, the quantity of interest, status
//
// Steady when, in an iteration that updated the drag, R_c < tol AND
// R_m < tol AND the relative change of the quantity of interest over the last
// `qoi_window` iterations is < tol
// (docs/SOLVER.md). Diverged when a residual or the QoI is not finite, or a
// residual exceeds `blowup` × its largest value in the first 5 iterations
// (at least 1e-2).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "flow/flow_state.h"
#include "job/result.h"

namespace gridfree {

struct SimpleSettings {
  double relax_u = 0.8;              // α_u, momentum under-relaxation
  double relax_p = 1.0;              // α_p (SIMPLEC needs none)
  // BiCGSTAB relative tolerance: 0.1 × the component's normalized residual,
  // clamped to [linear_floor, momentum_tolerance].
  double momentum_tolerance = 1e-2;
  double linear_floor = 1e-12;
  double pressure_tolerance = 1e-2;  // CG on p' (initial guess 0): reduction of ||b||
  int linear_max_iterations = 500;
  double steady_tolerance = 1e-5;
  int max_iterations = 20000;
  int min_iterations = 10;
  int qoi_window = 10;
  // Outer iterations between drag updates. β depends on the velocity only
  // through the slip Reynolds number; updating it every 4th iteration left
  // the iteration count (±5) and dp_star (within 5e-8) unchanged on the
  // bursting bubble and SSCP-like beds and cuts the filter's cost 4×
  // (docs/SOLVER.md).
  int drag_interval = 4;
  double blowup = 1e6;
  // Stop as not_converged when the residual has stalled over this many
  // iterations (flow/stall_monitor.h); 0 = off. The job's
  // numerics.stall_window on its own grid; nested_stall_window on the
  // coarse levels of the nested start.
  int stall_window = 0;
  // On the first stall, relax the deferred correction instead of stopping:
  // each new correction is blended with the last one used, weight
  // stalled_correction_weight on the new one (flow/momentum.h
  // CorrectionRelaxation); the stall window then starts again, and a second
  // stall ends the job (docs/SOLVER.md "Stalled outer iterations").
  bool relax_stalled_correction = false;
  double stalled_correction_weight = 0.5;
  // Anderson acceleration depth of the outer iterations (flow/anderson.h);
  // 0 = off (the default: see docs/DESIGN.md for what it measured).
  int anderson_depth = 0;
  // GMRES restart length m of the Newton–Krylov prototype (flow/newton_outer.h);
  // 0 = off: plain SIMPLEC (docs/DESIGN.md "Outer convergence").
  int newton_krylov_restart = 0;
  // Newton–Krylov only: recompute β, βv̄ in every evaluation of G (G is then
  // the drag-coupled map) instead of once per Newton step.
  bool newton_krylov_drag_in_map = false;
  // Two-grid FAS prototype (flow/two_grid_fas.h): fine SIMPLEC sweeps per
  // cycle (0 = off) and coarse sweeps per cycle.
  int fas_smoothing_sweeps = 0;
  int fas_coarse_sweeps = 10;
};

struct IterationReport {
  int iteration = 0;
  double continuity = 0;
  double momentum = 0;
  std::optional<double> qoi;
  double qoi_change = 0;
  int pressure_iterations = 0;
  int momentum_iterations = 0;
};

// Wall seconds spent in each step of the outer iterations.
struct PhaseSeconds {
  double drag = 0;      // drag update (per-particle drag, deposition, filter)
  double momentum = 0;  // assembly and solution of the three components
  double pressure = 0;  // pressure correction
};

struct SimpleOutcome {
  SolveStatus status = SolveStatus::kNotConverged;
  std::string reason;
  int iterations = 0;
  double continuity = 0;
  double momentum = 0;
  std::optional<double> qoi;
  double qoi_change = 0;
  // Estimated iterative error of the quantity of interest, relative, from
  // its last 2·qoi_window + 1 values (flow/iterative_error.h); absent when
  // the changes do not shrink geometrically.
  std::optional<double> qoi_iterative_error;
  PhaseSeconds seconds;
  bool linear_failures = false;  // some linear solve missed its tolerance
  bool stopped = false;          // LoopControl::stop_requested ended it early
  bool stalled = false;          // not_converged by the stall window, not by the iteration cap
  int correction_relaxed_from = 0;  // the iteration the stall remedy began at (0: never)
  int newton_steps = 0;          // Newton–Krylov only: steps taken
  int newton_fallbacks = 0;      // of which plain SIMPLEC steps (line search failed)
};

// Stop and resume (flow/checkpoint.h): the loop's own state, besides
// FlowState, that the next iteration needs.
struct LoopCounters {
  int iteration = 0;                 // outer iterations done
  std::vector<double> qoi_history;   // the last ≤ 2·qoi_window + 1 values, oldest first
  double first_continuity = -1;      // blow-up references (max of iterations 1–5)
  double first_momentum = -1;
};

struct LoopControl {
  const LoopCounters* resume = nullptr;  // continue after these (state holds p, u, β, βv̄)
  // Polled after every iteration that neither converged nor diverged; when
  // true, on_stop gets the state and counters and the loop returns with
  // SimpleOutcome::stopped set.
  std::function<bool()> stop_requested;
  std::function<void(const FlowState&, const LoopCounters&)> on_stop;
};

// Recomputes state.drag from state (β, βv̄ at cell centres).
using DragUpdate = std::function<void(const FlowState&, DragField&)>;
using QuantityOfInterest = std::function<double(const FlowState&)>;
using IterationCallback = std::function<void(const IterationReport&)>;

// Iterates `state` (ε_g, initial p and u set; ε̄ faces are derived here) to a
// steady state. `drag` may be empty (β kept as given), `qoi` may be empty.
SimpleOutcome run_simple(const FlowProblem& problem, const SimpleSettings& settings,
                         FlowState& state, const DragUpdate& drag,
                         const QuantityOfInterest& qoi, const IterationCallback& on_iteration,
                         const LoopControl& control = {});

}  // namespace gridfree
