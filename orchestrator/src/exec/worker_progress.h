// SPDX-License-Identifier: GPL-3.0-or-later
// The worker's progress file, <run folder>/progress.json (written by
// `gridfree-worker solve --progress`, docs/INTERFACE.md §2), and the one
// decision the executors take from it: how long a worker asked to stop may
// take before it is killed (docs/ORCHESTRATOR.md "Checkpoints").
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

namespace gridfree {

// <run_dir>/progress.json.
std::filesystem::path progress_file(const std::filesystem::path& run_dir);

// The progress file's object; nullopt when absent or unreadable (a job that
// has not reached its first iteration, or an older worker).
std::optional<nlohmann::json> read_job_progress(const std::filesystem::path& file);

// Seconds from SIGTERM to SIGKILL for a worker whose longest outer
// iteration so far took `longest_iteration_s`: time to finish the iteration
// it is in and write its checkpoint. base_s + 1.5 × longest_iteration_s,
// at least base_s, at most kMaxStopGraceSeconds; base_s when unknown.
double stop_grace_seconds(double base_s, std::optional<double> longest_iteration_s);

// The same for the worker of a run folder, from its progress file's
// `longest_iteration_s`.
double stop_grace_for_run(const std::filesystem::path& run_dir, double base_s);

// The longest a stop may wait for one worker (an hour).
inline constexpr double kMaxStopGraceSeconds = 3600.0;

}  // namespace gridfree
