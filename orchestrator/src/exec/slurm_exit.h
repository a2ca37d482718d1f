// SPDX-License-Identifier: GPL-3.0-or-later
// How a Slurm task that has left the queue ended, from what is left of it,
// in this order (docs/ORCHESTRATOR.md, "Watching"):
//
//   1. <run_dir>/exit_code, written by the batch script after the worker;
//   2. sacct's State|ExitCode (when the cluster keeps accounting);
//   3. <run_dir>/result.json: the worker finished but the script did not
//      (status converged -> exit 0, any other status -> exit 3);
//   4. nothing: lost (a retryable failure), or vanished (run again without
//      spending an attempt) when it ended while no gridfree process watched.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "exec/executor.h"

namespace gridfree {

std::optional<int> read_exit_code(const std::filesystem::path& run_dir);

// sacct -n -P -X -o State,ExitCode: "COMPLETED|0:0", "CANCELLED by 0|0:9" ...;
// nullopt when the line is not one.
std::optional<JobExit> exit_from_sacct(const std::string& line, const JobExit& base);

// The worker's exit code implied by its result file; nullopt without a
// readable result with a status.
std::optional<int> exit_code_from_result(const std::filesystem::path& result_json);

// Steps 1-4 above; `base` carries job id, run folder and wall time.
JobExit resolve_exit(const JobExit& base, const std::string& slurm_id, bool ended_unwatched);

}  // namespace gridfree
