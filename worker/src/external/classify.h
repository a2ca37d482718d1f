// SPDX-License-Identifier: GPL-3.0-or-later
// The outcome of an external job from what was seen in its case folder
// (docs/EXTERNAL.md "Classification"). Pure: the driver gathers the
// observations, classify_external decides. Rules, first match wins:
//   0 no record of the command's end (collect after a kill) failed
//   1 command not found (exit 127) / not executable (126)   failed
//   2 a failure pattern in stdout, stderr or a log file   failed
//   3 any other non-zero exit, or death by a signal         failed
//   4 the driver's own gridfree_result.json says so         its status
//   5 a quantity (or the residual) missing or not a number  failed
//   6 a quantity (or the residual) nan or inf               diverged
//   7 the residual above its tolerance                      not_converged (stalled)
//   8 a quantity's last two records differ by more than
//     steady_tolerance (relative)                           not_converged (iteration_cap)
//   else                                                    converged
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct ExternalExit {
  std::optional<int> code;    // exit code, if it exited
  std::optional<int> signal;  // signal number, if killed by one
};

struct FailureSighting {
  std::string pattern;
  std::string file;  // relative to case/: "stdout.log", "log.icoFoam"
  int line = 0;
  std::string text;
};

struct QuantitySighting {
  std::string name;
  std::string source;  // "postProcessing/fo/0/volFieldValue.dat", "log.icoFoam"
  std::optional<double> last;
  std::optional<double> previous;
  std::string problem;  // why `last` is missing
};

struct ResidualSighting {
  std::string source;
  std::optional<double> last;
  std::string problem;
  double tolerance = 0;
};

// What the command's own result file (case/gridfree_result.json) said,
// beyond its quantities.
struct DriverVerdict {
  std::string status;  // "converged", "not_converged", "diverged", "failed"
  std::string reason;
};

struct ExternalSightings {
  std::optional<ExternalExit> exit;  // empty: not recorded (the run did not finish)
  std::string stderr_tail;           // the last non-empty lines of stderr (" | "), for context
  std::optional<FailureSighting> failure;
  std::optional<DriverVerdict> driver;
  std::vector<QuantitySighting> quantities;
  std::optional<ResidualSighting> residual;
  std::optional<double> steady_tolerance;
};

struct ExternalClassification {
  std::string status;   // converged, not_converged, diverged, failed
  std::string outcome;  // converged, stalled, iteration_cap, diverged, failed
  std::string reason;
};

ExternalClassification classify_external(const ExternalSightings& s);

// Relative change between two records: |a − b| / max(|a|, |b|) (0 when both are 0).
double relative_change(double last, double previous);

// "SIGSEGV" for 11, "signal 42" for one without a name.
std::string signal_name(int signal);

}  // namespace gridfree
