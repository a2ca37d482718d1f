// SPDX-License-Identifier: GPL-3.0-or-later
// Newton–Krylov outer iterations on the SIMPLEC sweep (newton_outer.h).
#include "flow/newton_outer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "flow/anderson.h"
#include "flow/newton_krylov.h"
#include "flow/parallel.h"
#include "flow/residuals.h"
#include "flow/outer_status.h"
#include "flow/simplec_sweep.h"

namespace gridfree {
namespace {

void unpack(const std::vector<double>& x, FaceVector& u, std::vector<double>& p) {
  std::size_t off = 0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t i = 0; i < u[a].size(); ++i) u[a][i] = x[off++];
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = x[off++];
}

// w_i = 1/(2 n_u RMS(u)²) on the velocity entries and 1/(2 n_p RMS(p)²) on
// the pressure entries, so ‖x‖ = 1 (a zero block gets the weight of RMS 1).
std::vector<double> block_weights(const std::vector<double>& x, std::size_t velocity_entries) {
  const std::size_t np = x.size() - velocity_entries;
  const double su = deterministic_sum(velocity_entries, [&](std::size_t i) { return x[i] * x[i]; });
  const double sp = deterministic_sum(np, [&](std::size_t i) { return x[velocity_entries + i] * x[velocity_entries + i]; });
  const double wu = 1.0 / (2.0 * (su > 0 ? su : double(velocity_entries)));
  const double wp = 1.0 / (2.0 * (sp > 0 ? sp : double(np)));
  std::vector<double> w(x.size(), wp);
  std::fill(w.begin(), w.begin() + long(velocity_entries), wu);
  return w;
}

}  // namespace

SimpleOutcome run_newton_krylov(const FlowProblem& problem, const SimpleSettings& settings, FlowState& state,
                                const DragUpdate& drag, const QuantityOfInterest& qoi,
                                const IterationCallback& on_iteration, const LoopControl& control) {
  const Grid& g = problem.grid;
  auto ws = std::make_unique<SweepWorkspace>(g);
  update_eps_faces(problem, state);
  apply_fixed_faces(problem, state);
  if (state.drag.beta.empty()) state.drag.beta.assign(g.cells(), 0.0);

  SimpleOutcome out;
  NewtonKrylovSettings nk_settings;
  nk_settings.restart = settings.newton_krylov_restart;
  NewtonKrylov nk(nk_settings, {});
  const std::size_t velocity_entries = state.u[0].size() + state.u[1].size() + state.u[2].size();
  double first_continuity = -1, first_momentum = -1;
  std::optional<double> previous_qoi;
  int evaluations = control.resume ? control.resume->iteration : 0;

  // f = G(x) − x; state holds G(x) afterwards.
  SweepCounts counts;
  auto evaluate = [&](const std::vector<double>& x, std::vector<double>& f, const SweepCounts* replay) {
    unpack(x, state.u, state.p);
    if (drag && settings.newton_krylov_drag_in_map) {
      const auto t0 = std::chrono::steady_clock::now();
      drag(state, state.drag);
      out.seconds.drag += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    const SweepReport r = simplec_sweep(problem, settings, state, *ws, &out.seconds, replay);
    ++evaluations;
    if (r.linear_failures) out.linear_failures = true;
    AndersonMixer::pack(state.u, state.p, f);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] -= x[i];
    return r;
  };
  NewtonKrylovMaps maps;
  maps.residual = [&](const std::vector<double>& x, std::vector<double>& f) { evaluate(x, f, nullptr); };
  maps.directional = [&](const std::vector<double>& x, std::vector<double>& f) { evaluate(x, f, &counts); };

  std::vector<double> x, fx;
  AndersonMixer::pack(state.u, state.p, x);
  for (int step = 1;; ++step) {
    // 1. Drag from x_k, held for the step.
    unpack(x, state.u, state.p);
    auto t0 = std::chrono::steady_clock::now();
    if (drag && !settings.newton_krylov_drag_in_map) drag(state, state.drag);
    out.seconds.drag += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // 2. Base evaluation: the monitor, and the inner counts to replay.
    const SweepReport base = evaluate(x, fx, nullptr);
    counts = base.counts;
    IterationReport report = sweep_report(evaluations, base);
    monitor_qoi_step(qoi, state, previous_qoi, report);
    if (step == 1) {  // blow-up reference (at least 1e-2)
      first_continuity = std::max(report.continuity, 1e-2);
      first_momentum = std::max(report.momentum, 1e-2);
    }
    record_iteration(report, evaluations, out);
    if (on_iteration) on_iteration(report);

    // 3. Status.
    if (outer_diverged(report, settings.blowup, first_continuity, first_momentum)) {
      out.status = SolveStatus::kDiverged;
      out.reason = "diverged after " + std::to_string(evaluations) + " SIMPLEC sweeps (Newton-Krylov): " +
                   residuals_text(report.continuity, report.momentum);
      out.qoi.reset();
      return out;
    }
    const double tol = settings.steady_tolerance;
    if (step >= 2 && report.continuity < tol && report.momentum < tol && (!qoi || report.qoi_change < tol)) {
      out.status = SolveStatus::kConverged;
      return out;  // state = G(x_k)
    }
    if (evaluations >= settings.max_iterations) break;
    if (control.stop_requested && control.stop_requested()) {
      if (control.on_stop)
        control.on_stop(state, LoopCounters{evaluations, {}, first_continuity, first_momentum});
      out.stopped = true;
      return out;
    }

    // 4. Newton step (or the fallback x_{k+1} = G(x_k)).
    nk.set_weights(block_weights(x, velocity_entries));
    const NewtonStepReport rep = nk.step(maps, fx, x, tol);
    ++out.newton_steps;
    if (!rep.newton) ++out.newton_fallbacks;
  }
  out.status = SolveStatus::kNotConverged;
  out.reason =
      not_converged_reason(std::to_string(evaluations) + " SIMPLEC sweeps (Newton-Krylov)", out, settings.steady_tolerance);
  return out;
}

}  // namespace gridfree
