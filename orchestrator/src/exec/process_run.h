// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a command (argv, no shell) to completion and captures its stdout and
// stderr separately: the Slurm client commands are judged by both (sbatch
// prints the job id on stdout and its reasons for refusing on stderr).
#pragma once

#include <string>
#include <vector>

namespace gridfree {

struct ProcessOutput {
  int exit_code = -1;     // -1: could not be started or killed by a signal
  bool not_found = false; // the program is not on PATH (exec failed)
  std::string out, err;
};

// Searches PATH for argv[0]; extra_env entries ("NAME=value") are added to
// the child's environment.
ProcessOutput run_process(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env = {});

}  // namespace gridfree
