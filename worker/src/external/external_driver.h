// SPDX-License-Identifier: GPL-3.0-or-later
// The external driver behind `gridfree-worker solve` and `collect` for a job
// with /case/external (docs/EXTERNAL.md "How the driver runs your code"):
// check the template's hash, copy it to <run folder>/case/, render the
// placeholders, run the setup lines and the command, then collect the
// quantities and classify the outcome.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "external/classify.h"
#include "external/external_job.h"

namespace gridfree {

// What the driver writes into the case folder besides the command's output.
inline constexpr const char* kCaseFolder = "case";
inline constexpr const char* kCaseStdout = "stdout.log";
inline constexpr const char* kCaseStderr = "stderr.log";
inline constexpr const char* kCaseExitRecord = ".gridfree_exit";     // exit code, signal, timings
inline constexpr const char* kCaseOwnResult = "gridfree_result.json";  // written by the command, optionally

struct ExternalRunOptions {
  std::filesystem::path run_dir;           // case/ goes here
  std::string job_hash;
  std::string worker_version;              // the result's "version"
  std::function<bool()> stop_requested;    // polled while the command runs
  std::function<void(double elapsed_s)> on_tick;
  double stop_grace_s = 10;
  int cores = 1;                           // @@cores@@ (--threads; docs/EXTERNAL.md "Cores")
};

struct ExternalRunEnd {
  bool stopped = false;     // a stop was requested: no result
  nlohmann::json result;    // the result document (when not stopped)
  bool converged = false;
};

// Copies the template to run_dir/case (an old case/ removed first) and
// renders the `render` files; @@cores@@ is `cores` unless the job defines
// a variable of that name (a job document written by hand). Throws InputError (the render entry's JSON
// pointer; file, line and name of an undefined placeholder) and
// std::runtime_error (the file system).
void prepare_external_case(const ExternalJob& job, const std::filesystem::path& run_dir, int cores = 1);

// The whole run. Template problems (changed since planning, unreadable)
// and a command that cannot be run give a failed result, not an exception.
ExternalRunEnd run_external_job(const ExternalJob& job, const ExternalRunOptions& options);

// The result from an existing run_dir/case without running anything; the
// exit code and timings from case/.gridfree_exit when it is there.
nlohmann::json collect_external_job(const ExternalJob& job, const ExternalRunOptions& options);

// The sightings classify_external decides from, read from `case_dir`, and
// the quantities that were read (name → value).
ExternalSightings gather_sightings(const ExternalJob& job, const std::filesystem::path& case_dir,
                                   const std::optional<ExternalExit>& exit);

}  // namespace gridfree
