// SPDX-License-Identifier: GPL-3.0-or-later
// The outer loops' divergence test and reasons (outer_status.h).
#include "flow/outer_status.h"

#include <cmath>
#include <sstream>
#include <vector>

#include "flow/residuals.h"

namespace gridfree {

std::string residual_text(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

IterationReport sweep_report(int iteration, const SweepReport& sweep) {
  IterationReport r;
  r.iteration = iteration;
  r.continuity = sweep.continuity;
  r.momentum = sweep.momentum;
  r.momentum_iterations = sweep.momentum_iterations;
  r.pressure_iterations = sweep.pressure_iterations;
  return r;
}

void monitor_qoi_step(const QuantityOfInterest& qoi, const FlowState& state, std::optional<double>& previous,
                      IterationReport& r) {
  r.qoi_change = 1.0;
  if (!qoi) return;
  r.qoi = qoi(state);
  if (previous) r.qoi_change = normalized(std::abs(*r.qoi - *previous), std::abs(*r.qoi));
  previous = r.qoi;
}

void record_iteration(const IterationReport& r, int iterations, SimpleOutcome& out) {
  out.iterations = iterations;
  out.continuity = r.continuity;
  out.momentum = r.momentum;
  out.qoi = r.qoi;
  out.qoi_change = r.qoi_change;
}

bool outer_diverged(const IterationReport& r, double blowup, double first_continuity, double first_momentum) {
  const bool bad = !std::isfinite(r.continuity) || !std::isfinite(r.momentum) || (r.qoi && !std::isfinite(*r.qoi));
  return bad || r.continuity > blowup * first_continuity || r.momentum > blowup * first_momentum;
}

bool stall_is_divergence(const IterationReport& r) {
  return r.qoi.has_value() && !(r.qoi_change < kStallUnsettledQoiChange);
}

std::string residuals_text(double continuity, double momentum) {
  return "continuity residual " + residual_text(continuity) + ", momentum residual " + residual_text(momentum);
}

std::string not_converged_reason(const std::string& count, const SimpleOutcome& out, double tolerance) {
  return "not converged after " + count + ": " + residuals_text(out.continuity, out.momentum) +
         ", relative change of the quantity of interest " + residual_text(out.qoi_change) + " (tolerance " +
         residual_text(tolerance) + ")";
}

std::string steady_check_note(const std::optional<SteadyCheck>& last, int drag_interval, int min_iterations,
                              double tolerance) {
  if (drag_interval <= 1) return {};
  std::string out = "; the steady criterion is checked on drag-update iterations (every " +
                    std::to_string(drag_interval) + (drag_interval == 2 ? "nd" : drag_interval == 3 ? "rd" : "th") +
                    ")";
  if (!last) return out + "; none was checked";
  std::vector<std::string> failed;
  const std::string tol = residual_text(tolerance);
  if (last->iteration < min_iterations)
    failed.push_back("the minimum of " + std::to_string(min_iterations) + " iterations");
  if (!(last->continuity < tolerance))
    failed.push_back("the continuity residual " + residual_text(last->continuity) + " ≥ " + tol);
  if (!(last->momentum < tolerance))
    failed.push_back("the momentum residual " + residual_text(last->momentum) + " ≥ " + tol);
  if (last->qoi_change && !(*last->qoi_change < tolerance))
    failed.push_back("the relative change of the quantity of interest " + residual_text(*last->qoi_change) +
                     " ≥ " + tol);
  out += "; the last check, at iteration " + std::to_string(last->iteration) + ", failed on ";
  for (std::size_t i = 0; i < failed.size(); ++i) out += (i ? (i + 1 == failed.size() ? " and " : ", ") : "") + failed[i];
  if (failed.empty()) out += "nothing (it passed)";
  return out;
}

}  // namespace gridfree
