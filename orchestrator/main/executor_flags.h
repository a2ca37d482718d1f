// SPDX-License-Identifier: GPL-3.0-or-later
// --executor and the Slurm settings flags shared by `run` and `daemon`
// (docs/ORCHESTRATOR.md, "Slurm settings"): profile file < flags.
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "exec/executor.h"
#include "exec/slurm_settings.h"
#include "sched/scheduler.h"

namespace gridfree::cli {

struct ExecutorFlags {
  std::string kind = "local";
  std::string profile;          // --slurm-profile FILE
  SlurmSettings slurm;          // flags (override the profile)
  double margin = 0;            // 0 = not given
};

void add_executor_flags(CLI::App* sub, ExecutorFlags& flags);

// The executor the flags name, with `options` adjusted to it: for Slurm,
// jobs in flight = max_queued, -j = tasks running at once (the array
// throttle), threads = cpus per task, run folders in runs_dir if given.
// `study_slurm`: the study's "slurm" object, or null (profile < study < flags).
// `env`: where PATH (the Slurm commands must be on it, else InputError) and
// the SBATCH_* input variables (SlurmSettings::environment) are read.
std::unique_ptr<Executor> make_executor(const ExecutorFlags& flags, const std::string& db, int jobs,
                                        SchedulerOptions& options, const nlohmann::json* study_slurm = nullptr,
                                        const EnvLookup& env = process_environment());

}  // namespace gridfree::cli
