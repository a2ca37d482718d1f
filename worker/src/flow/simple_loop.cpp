// SPDX-License-Identifier: GPL-3.0-or-later
// The SIMPLEC outer loop (simple_loop.h): a handful of named steps.
#include "flow/simple_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>

#include "flow/anderson.h"
#include "flow/iterative_error.h"
#include "flow/outer_status.h"
#include "flow/residuals.h"
#include "flow/simplec_sweep.h"
#include "flow/stall_monitor.h"
#include "flow/phase_clock.h"

namespace gridfree {
SimpleOutcome run_simple(const FlowProblem& problem, const SimpleSettings& settings,
                         FlowState& state, const DragUpdate& drag,
                         const QuantityOfInterest& qoi, const IterationCallback& on_iteration,
                         const LoopControl& control) {
  const Grid& g = problem.grid;
  auto ws = std::make_unique<SweepWorkspace>(g);
  update_eps_faces(problem, state);
  apply_fixed_faces(problem, state);
  if (state.drag.beta.empty()) state.drag.beta.assign(g.cells(), 0.0);

  SimpleOutcome out;
  std::deque<double> qoi_history;
  double first_continuity = -1, first_momentum = -1;
  std::unique_ptr<AndersonMixer> mixer;
  std::vector<double> x_entering;
  if (settings.anderson_depth > 0) mixer = std::make_unique<AndersonMixer>(settings.anderson_depth);
  std::optional<StallMonitor> stall;
  if (settings.stall_window > 0) stall.emplace(settings.stall_window);

  std::optional<SteadyCheck> last_check;  // the last iteration the steady criterion looked at
  int first_iteration = 1;
  if (control.resume) {
    first_iteration = control.resume->iteration + 1;
    qoi_history.assign(control.resume->qoi_history.begin(), control.resume->qoi_history.end());
    first_continuity = control.resume->first_continuity;
    first_momentum = control.resume->first_momentum;
  }

  for (int it = first_iteration; it <= settings.max_iterations; ++it) {
    PhaseClock clock;
    // 1. Drag from the current velocity field.
    const bool drag_fresh = !drag || (it - 1) % std::max(1, settings.drag_interval) == 0;
    if (drag && drag_fresh) drag(state, state.drag);
    clock.charge(out.seconds.drag);

    if (mixer) AndersonMixer::pack(state.u, state.p, x_entering);
    // 2–3. Momentum predictor and pressure correction (simplec_sweep.h).
    const SweepReport sweep = simplec_sweep(problem, settings, state, *ws, &out.seconds);
    if (sweep.linear_failures) out.linear_failures = true;
    if (mixer) mixer->mix(x_entering, state.u, state.p);

    // 4. Monitor: residuals, quantity of interest, status.
    IterationReport report = sweep_report(it, sweep);
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
    record_iteration(report, it, out);
    if (qoi) out.qoi_iterative_error = geometric_iterative_error(qoi_history, settings.qoi_window);
    if (on_iteration) on_iteration(report);

    if (outer_diverged(report, settings.blowup, first_continuity, first_momentum)) {
      out.status = SolveStatus::kDiverged;
      out.reason = "diverged at iteration " + std::to_string(it) + ": " +
                   residuals_text(report.continuity, report.momentum);
      out.qoi.reset();
      return out;
    }
    const double tol = settings.steady_tolerance;
    // Steady only in an iteration that updated the drag: its β comes from
    // the iterate it started from, as with an update every iteration.
    if (drag_fresh) last_check = SteadyCheck{it, report.continuity, report.momentum,
                                             qoi ? std::optional<double>(report.qoi_change) : std::nullopt};
    if (it >= settings.min_iterations && drag_fresh && report.continuity < tol && report.momentum < tol &&
        (!qoi || report.qoi_change < tol)) {
      out.status = SolveStatus::kConverged;
      return out;
    }
    bool stalled = stall && stall->stalled(std::max(report.continuity, report.momentum));
    if (stalled && settings.relax_stalled_correction && !ws->relaxed_correction && !stall_is_divergence(report)) {
      // A limit cycle: relax the deferred correction and give it a new window.
      ws->relaxed_correction = std::make_unique<CorrectionRelaxation>(settings.stalled_correction_weight);
      out.correction_relaxed_from = it;
      stall.emplace(settings.stall_window);
      stalled = false;
    }
    if (stalled) {
      if (stall_is_divergence(report)) {  // no limit cycle: the quantity of interest itself wanders
        out.status = SolveStatus::kDiverged;
        out.reason = "diverged: no progress in " + std::to_string(settings.stall_window) + " iterations at iteration " +
                     std::to_string(it) + " with the quantity of interest still changing by " +
                     residual_text(report.qoi_change) + " (a stall needs less than " +
                     residual_text(kStallUnsettledQoiChange) + "): " +
                     residuals_text(report.continuity, report.momentum);
        out.qoi.reset();
        return out;
      }
      out.status = SolveStatus::kNotConverged;
      out.stalled = true;
      out.reason = not_converged_reason("stalling for " + std::to_string(settings.stall_window) +
                                            " iterations at iteration " + std::to_string(it),
                                        out, tol);
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
  out.reason = not_converged_reason(std::to_string(settings.max_iterations) + " iterations", out,
                                    settings.steady_tolerance) +
               (drag ? steady_check_note(last_check, settings.drag_interval, settings.min_iterations,
                                         settings.steady_tolerance)
                     : std::string());
  return out;
}

}  // namespace gridfree
