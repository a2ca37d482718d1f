// The outer loops' divergence test and reasons (outer_status.h).
#include "flow/outer_status.h"

#include <cmath>
#include <sstream>

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

std::string residuals_text(double continuity, double momentum) {
  return "continuity residual " + residual_text(continuity) + ", momentum residual " + residual_text(momentum);
}

std::string not_converged_reason(const std::string& count, const SimpleOutcome& out, double tolerance) {
  return "not converged after " + count + ": " + residuals_text(out.continuity, out.momentum) +
         ", relative change of the quantity of interest " + residual_text(out.qoi_change) + " (tolerance " +
         residual_text(tolerance) + ")";
}

}  // namespace gridfree
