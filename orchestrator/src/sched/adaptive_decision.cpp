// SPDX-License-Identifier: GPL-3.0-or-later
// decide_adaptive_step (sched/adaptive_decision.h).
#include "sched/adaptive_decision.h"

#include "study/format_number.h"

#include <cmath>
#include <cstdio>

#include "study/study_plan.h"

namespace gridfree {
namespace {

std::string percent(double fraction) { return format_number("%.3g", 100 * fraction) + " %"; }

std::string core_hours(double cpu_s) {
  return std::isnan(cpu_s) ? std::string("unknown core-hours (no cost figure yet)")
                           : format_number("%.3g", cpu_s / 3600) + " core-hours";
}

// The ladder's axis: Δ* for gridfree's own cases, h for an external case's.
std::string axis(const AdaptiveGrids& a) { return a.variable ? "h " : "Δ* "; }

// "best: Δ* 0.69, RDE 1.4 % (verdict pre-asymptotic), f0 = 1012.4".
std::string best_figure(const AdaptiveGrids& a, const AdaptiveFit& fit) {
  if (!fit.finest_delta_star || !fit.finest_rde) return "no extrapolation (" + std::to_string(fit.ng) + " converged grids)";
  std::string out = "best: " + axis(a) + format_number("%.3g", *fit.finest_delta_star) + ", RDE " + percent(*fit.finest_rde) +
                    " (verdict " + (fit.verdict.empty() ? "none" : fit.verdict) + ")";
  if (fit.f0) out += ", f0 = " + format_number("%.6g", *fit.f0);
  return out;
}

}  // namespace

std::string adaptive_status_word(AdaptiveDecision::Kind kind) {
  switch (kind) {
    case AdaptiveDecision::Kind::kTargetMet: return "target_met";
    case AdaptiveDecision::Kind::kTargetNotReached: return "target_not_reached";
    default: return "refining";
  }
}

namespace {

AdaptiveDecision decide(const AdaptiveGrids& a, const std::vector<AdaptiveRung>& ladder,
                                      std::size_t started, const AdaptiveFit& fit, double scale,
                                      double machine_memory) {
  AdaptiveDecision d;
  const std::string target = percent(a.target_rde);
  for (std::size_t k = started; k < ladder.size(); ++k) d.saved_cpu_s += scale * ladder[k].model_cpu_s;
  d.rungs_not_run = started < ladder.size() ? ladder.size() - started : 0;
  const std::string not_run = std::to_string(d.rungs_not_run) + " grid(s) down to " + axis(a) +
                              format_number("%.3g", ladder.empty() ? 0.0 : ladder.back().delta_star) + " not run";
  const std::string at =
      fit.finest_delta_star ? axis(a) + format_number("%.3g", *fit.finest_delta_star) : "no converged grid";
  // 1. target met
  const bool enough = fit.ng >= static_cast<int>(AdaptiveGrids::kFirstGrids);
  if (enough && fit.verdict == "converged" && fit.finest_rde && *fit.finest_rde <= a.target_rde) {
    d.kind = AdaptiveDecision::Kind::kTargetMet;
    d.message = "stopped at " + at + ": RDE " + percent(*fit.finest_rde) + " ≤ " + target + " (verdict converged";
    if (fit.f0) d.message += ", f0 = " + format_number("%.6g", *fit.f0);
    d.message += "); saved an estimated " + core_hours(d.saved_cpu_s) + " (" + not_run + ")";
    return d;
  }
  // Why the target is not met yet.
  std::string why;
  if (!enough)
    why = std::to_string(fit.ng) + " converged grid(s) < " + std::to_string(AdaptiveGrids::kFirstGrids) +
          ": no extrapolation yet";
  else if (fit.verdict != "converged")
    why = "verdict " + (fit.verdict.empty() ? std::string("none") : fit.verdict) + " (not converged)";
  else
    why = "RDE " + (fit.finest_rde ? percent(*fit.finest_rde) : std::string("unknown")) + " > " + target;
  // 2. ladder end
  if (started >= ladder.size()) {
    d.kind = AdaptiveDecision::Kind::kTargetNotReached;
    const std::string end = a.variable ? "the ladder's finest grid (" + a.variable->name + " = " +
                                             format_number("%.6g", a.variable->finest) + ")"
                                       : "finest_delta_star " + format_number("%.3g", a.finest_delta_star);
    d.message = "target not reached: " + why + " at " + at + " and " + end + " reached; " + best_figure(a, fit);
    return d;
  }
  // 3. caps on the next rung
  const AdaptiveRung& next = ladder[started];
  const double mem_cap = a.max_memory_bytes ? *a.max_memory_bytes : machine_memory;
  const std::string mem_name = a.max_memory_bytes ? "max_memory" : "this machine's memory";
  std::string cap;
  if (mem_cap > 0 && next.memory_bytes > mem_cap)
    cap = "would need an estimated " + human_bytes(next.memory_bytes) + " > " + mem_name + " " + human_bytes(mem_cap);
  else if (a.max_cpu_s && scale * next.model_cpu_s > *a.max_cpu_s)
    cap = "would need an estimated " + format_number("%.3g", scale * next.model_cpu_s) + " CPU s > max_cpu_s " +
          format_number("%.3g", *a.max_cpu_s);
  if (!cap.empty()) {
    d.kind = AdaptiveDecision::Kind::kTargetNotReached;
    d.message = "target not reached: " + why + " at " + at + "; the next grid " + axis(a) + format_number("%.3g", next.delta_star) +
                " " + cap + "; " + best_figure(a, fit) + "; " + not_run + " (an estimated " + core_hours(d.saved_cpu_s) + ")";
    return d;
  }
  // 4. continue
  d.kind = AdaptiveDecision::Kind::kContinue;
  d.next_rung = started;
  d.saved_cpu_s = 0;
  d.rungs_not_run = 0;
  const std::string grid = next.label.empty() ? std::to_string(next.cells[0]) + "x" + std::to_string(next.cells[1]) +
                                                   "x" + std::to_string(next.cells[2])
                                             : next.label;
  const std::string cost = std::isnan(next.model_cpu_s)
                               ? std::string("cost unknown")
                               : "an estimated " + format_number("%.3g", scale * next.model_cpu_s) + " CPU s";
  d.message = "refining: " + why + " at " + at + "; next grid " + axis(a) + format_number("%.3g", next.delta_star) +
              " (" + grid + ", " + cost + ")";
  return d;
}

}  // namespace

AdaptiveDecision decide_adaptive_step(const AdaptiveGrids& a, const std::vector<AdaptiveRung>& ladder,
                                      std::size_t started, const AdaptiveFit& fit, double scale,
                                      double machine_memory) {
  AdaptiveDecision d = decide(a, ladder, started, fit, scale, machine_memory);
  if (!fit.window.empty()) d.message += "; " + fit.window;
  return d;
}

}  // namespace gridfree
