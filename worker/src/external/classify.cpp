// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/classify.h"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>

namespace gridfree {
namespace {

std::string classify_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string with_stderr(const std::string& reason, const std::string& tail) {
  return tail.empty() ? reason : reason + " (stderr: " + tail + ")";
}

ExternalClassification classified(const char* status, const char* outcome, std::string reason) {
  return {status, outcome, std::move(reason)};
}

}  // namespace

double relative_change(double last, double previous) {
  const double scale = std::max(std::fabs(last), std::fabs(previous));
  return scale == 0 ? 0.0 : std::fabs(last - previous) / scale;
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGKILL: return "SIGKILL";
    case SIGINT: return "SIGINT";
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGFPE: return "SIGFPE";
    case SIGBUS: return "SIGBUS";
    case SIGILL: return "SIGILL";
    case SIGPIPE: return "SIGPIPE";
    case SIGHUP: return "SIGHUP";
    case SIGXCPU: return "SIGXCPU";
    default: return "signal " + std::to_string(signal);
  }
}

ExternalClassification classify_external(const ExternalSightings& s) {
  // 0. No record of the command's end: it did not finish under a worker
  // (killed with it, or still running), so its files may be partial.
  if (!s.exit)
    return classified("failed", "failed",
                      "no record of how the command ended (case/.gridfree_exit): the run did not finish");
  // 1. The command could not be started (the shell's and the driver's codes).
  if (s.exit && s.exit->code == 127)
    return classified("failed", "failed", with_stderr("command not found (exit code 127)", s.stderr_tail));
  if (s.exit && s.exit->code == 126)
    return classified("failed", "failed", with_stderr("command not executable (exit code 126)", s.stderr_tail));
  // 2. A declared failure pattern (with stderr's tail unless the line is stderr's).
  if (s.failure)
    return classified("failed", "failed",
                      with_stderr("failure pattern \"" + s.failure->pattern + "\" at line " +
                                      std::to_string(s.failure->line) + " of " + s.failure->file + ": " +
                                      s.failure->text,
                                  s.failure->file == "stderr.log" ? std::string() : s.stderr_tail));
  // 3. Any other unsuccessful end.
  if (s.exit && s.exit->signal)
    return classified("failed", "failed",
                      with_stderr("killed by " + signal_name(*s.exit->signal), s.stderr_tail));
  if (s.exit && s.exit->code && *s.exit->code != 0)
    return classified("failed", "failed",
                      with_stderr("exit code " + std::to_string(*s.exit->code), s.stderr_tail));
  // 4. The command's own verdict.
  if (s.driver && s.driver->status != "converged") {
    const std::string reason = "the command's gridfree_result.json says " + s.driver->status +
                               (s.driver->reason.empty() ? "" : ": " + s.driver->reason);
    if (s.driver->status == "diverged") return classified("diverged", "diverged", reason);
    if (s.driver->status == "not_converged") return classified("not_converged", "iteration_cap", reason);
    return classified("failed", "failed", reason);
  }
  // 5. Something to read is not there.
  for (const auto& q : s.quantities)
    if (!q.last) return classified("failed", "failed", "quantity " + q.name + " missing: " + q.problem);
  if (s.residual && !s.residual->last)
    return classified("failed", "failed", "residual missing: " + s.residual->problem);
  // 6. Not a finite number.
  for (const auto& q : s.quantities)
    if (!std::isfinite(*q.last))
      return classified("diverged", "diverged",
                        "quantity " + q.name + " is " + classify_number(*q.last) + " in " + q.source);
  if (s.residual && !std::isfinite(*s.residual->last))
    return classified("diverged", "diverged", "residual is " + classify_number(*s.residual->last) + " in " + s.residual->source);
  // 7. The residual did not come down far enough.
  if (s.residual && *s.residual->last > s.residual->tolerance)
    return classified("not_converged", "stalled",
                      "residual " + classify_number(*s.residual->last) + " above the tolerance " +
                          classify_number(s.residual->tolerance) + " (last value in " + s.residual->source + ")");
  // 8. A quantity still moving between its last two records.
  if (s.steady_tolerance)
    for (const auto& q : s.quantities)
      if (q.previous && std::isfinite(*q.previous)) {
        const double change = relative_change(*q.last, *q.previous);
        if (change > *s.steady_tolerance)
          return classified("not_converged", "iteration_cap",
                            "quantity " + q.name + " still changing: " + classify_number(change) +
                                " between the last two records of " + q.source + " (steady_tolerance " +
                                classify_number(*s.steady_tolerance) + ")");
      }
  std::string reason = "exit code 0";
  reason += ", " + std::to_string(s.quantities.size()) + " quantit" + (s.quantities.size() == 1 ? "y" : "ies") + " read";
  if (s.residual)
    reason += ", residual " + classify_number(*s.residual->last) + " ≤ " + classify_number(s.residual->tolerance);
  return classified("converged", "converged", reason);
}

}  // namespace gridfree
