// SPDX-License-Identifier: GPL-3.0-or-later
// Process exit codes shared by both executables (docs/INTERFACE.md §2, §4).
#pragma once

namespace gridfree {

enum class ExitCode : int {
  kOk = 0,             // success; for a solve: converged
  kInternalError = 1,  // a bug or an environment failure
  kInvalidInput = 2,   // the input is wrong; the message names the field
  kNotConverged = 3,   // ran, but did not converge / diverged / some jobs failed
  kInterrupted = 130,  // SIGINT / SIGTERM
};

constexpr int to_int(ExitCode c) { return static_cast<int>(c); }

}  // namespace gridfree
