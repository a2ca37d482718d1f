// SPDX-License-Identifier: GPL-3.0-or-later
// Two-grid FAS cycles with SIMPLEC smoothing (two_grid_fas.h).
#include "flow/two_grid_fas.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "flow/flow_residuals.h"
#include "flow/prolong.h"
#include "flow/residuals.h"
#include "flow/outer_status.h"
#include "flow/simplec_sweep.h"

namespace gridfree {
namespace {

// I(r_h / V_h) − r_H / V_H on the coarse lattice.
std::vector<double> tau_source(const std::vector<double>& restricted_density, const std::vector<double>& coarse_residual,
                               double coarse_volume) {
  std::vector<double> s(coarse_residual.size());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = restricted_density[i] - coarse_residual[i] / coarse_volume;
  return s;
}

}  // namespace

FasOutcome run_two_grid_fas(const FasLevel& fine, FasLevel& coarse, const SimpleSettings& settings,
                            const QuantityOfInterest& qoi, const IterationCallback& on_iteration) {
  const FlowProblem& ph = *fine.problem;
  FlowState& sh = *fine.state;
  const Grid& gh = ph.grid;
  const Grid& gH = coarse.problem->grid;
  auto ws = std::make_unique<SweepWorkspace>(gh);
  update_eps_faces(ph, sh);
  apply_fixed_faces(ph, sh);
  if (sh.drag.beta.empty()) sh.drag.beta.assign(gh.cells(), 0.0);
  FlowState& sH = *coarse.state;
  update_eps_faces(*coarse.problem, sH);

  FasOutcome fas;
  SimpleOutcome& out = fas.outcome;
  double first_continuity = -1, first_momentum = -1;
  std::optional<double> previous_qoi;
  const int nu = std::max(1, settings.fas_smoothing_sweeps);
  SimpleSettings coarse_settings = settings;
  coarse_settings.max_iterations = std::max(1, settings.fas_coarse_sweeps);
  coarse_settings.min_iterations = 1;

  for (int cycle = 1;; ++cycle) {
    // 1–2. Drag, smoothing sweeps.
    auto t0 = std::chrono::steady_clock::now();
    if (fine.drag) fine.drag(sh, sh.drag);
    out.seconds.drag += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    SweepReport sweep;
    for (int k = 0; k < nu; ++k) {
      sweep = simplec_sweep(ph, settings, sh, *ws, &out.seconds);
      if (sweep.linear_failures) out.linear_failures = true;
      ++out.iterations;
    }
    IterationReport report = sweep_report(out.iterations, sweep);
    monitor_qoi_step(qoi, sh, previous_qoi, report);
    if (cycle == 1) {
      first_continuity = std::max(report.continuity, 1e-2);
      first_momentum = std::max(report.momentum, 1e-2);
    }
    record_iteration(report, out.iterations, out);
    if (on_iteration) on_iteration(report);
    if (outer_diverged(report, settings.blowup, first_continuity, first_momentum)) {
      out.status = SolveStatus::kDiverged;
      out.reason = "diverged after " + std::to_string(out.iterations) + " fine sweeps (two-grid FAS): " +
                   residuals_text(report.continuity, report.momentum);
      out.qoi.reset();
      return fas;
    }
    const double tol = settings.steady_tolerance;
    if (cycle >= 2 && report.continuity < tol && report.momentum < tol && (!qoi || report.qoi_change < tol)) {
      out.status = SolveStatus::kConverged;
      return fas;
    }
    if (out.iterations >= settings.max_iterations) break;

    // 3. Restriction of the state and of the residual densities.
    const FaceVector u_hat = prolong_faces(gh, sh.u, gH);
    const CellField p_hat = prolong_cells(gh, sh.p, gH);
    FaceVector r_h = momentum_residuals(ph, sh);
    CellField c_h = continuity_residuals(ph, sh);
    const double vh = gh.cell_volume(), vH = gH.cell_volume();
    for (int a = 0; a < 3; ++a)
      for (double& v : r_h[a].values) v /= vh;
    for (double& v : c_h) v /= vh;
    const FaceVector r_density = prolong_faces(gh, r_h, gH);
    const CellField c_density = prolong_cells(gh, c_h, gH);

    // 4. τ: the coarse residuals at the restricted state, without sources.
    FlowProblem pH = *coarse.problem;
    pH.sources = nullptr;
    sH.u = u_hat;
    sH.p = p_hat;
    apply_fixed_faces(pH, sH);
    if (coarse.drag) coarse.drag(sH, sH.drag);
    const FaceVector r_H = momentum_residuals(pH, sH);
    const CellField c_H = continuity_residuals(pH, sH);
    FlowSources sources;
    for (int a = 0; a < 3; ++a) sources.momentum[std::size_t(a)] = tau_source(r_density[a].values, r_H[a].values, vH);
    sources.mass = tau_source(c_density, c_H, vH);
    pH.sources = &sources;

    // 5. Coarse iterations with the τ sources.
    const FaceVector u_start = sH.u;
    const SimpleOutcome co = run_simple(pH, coarse_settings, sH, coarse.drag, {}, {});
    fas.coarse_sweeps += co.iterations;

    // 6. Correction.
    FaceVector du = sH.u;
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < du[a].size(); ++i) du[a][i] -= u_start[a][i];
    CellField dp = sH.p;
    for (std::size_t i = 0; i < dp.size(); ++i) dp[i] -= p_hat[i];
    const FaceVector du_h = prolong_faces(gH, du, gh);
    const CellField dp_h = prolong_cells(gH, dp, gh);
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < sh.u[a].size(); ++i) sh.u[a][i] += du_h[a][i];
    for (std::size_t i = 0; i < sh.p.size(); ++i) sh.p[i] += dp_h[i];
    apply_fixed_faces(ph, sh);
    ++fas.cycles;
  }
  out.status = SolveStatus::kNotConverged;
  out.reason =
      not_converged_reason(std::to_string(out.iterations) + " fine sweeps (two-grid FAS)", out, settings.steady_tolerance);
  return fas;
}

}  // namespace gridfree
