// SPDX-License-Identifier: GPL-3.0-or-later
// The batch script and sbatch command line of a Slurm job array: task i
// runs the worker (the same command as LocalExecutor, docs/INTERFACE.md) in
// the i-th run folder, after the profile's setup lines, and saves its exit
// code to <run folder>/exit_code. Every path is single-quoted in the script
// and passed to sbatch as its own argv word (spaces are safe).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "exec/executor.h"
#include "exec/slurm_settings.h"

namespace gridfree {

// Seconds before the time limit at which Slurm sends SIGTERM to the batch
// shell (--signal=B:TERM@120): time for the worker to finish its outer
// iteration and write its checkpoint before SIGKILL. A job resubmitted
// after a stop gets more when its earlier attempt's outer iterations were
// long (SlurmArray::stop_lead_s).
inline constexpr int kSlurmStopLeadSeconds = 120;

struct SlurmArray {
  std::string name;                              // --job-name
  std::vector<std::filesystem::path> run_dirs;   // task i -> run_dirs[i]
  int threads = 1;                               // worker --threads
  std::filesystem::path bed_cache;               // worker --bed-cache (empty: none)
  int cpus = 1;                                  // --cpus-per-task
  int tasks = 1;                                 // --ntasks (given when > 1)
  long time_minutes = 0;                         // --time (0 = not given)
  long mem_mb = 0;                               // --mem (0 = not given)
  int throttle = 0;                              // %N (0 = none)
  int stop_lead_s = kSlurmStopLeadSeconds;       // --signal=B:TERM@stop_lead_s
  // Where the time limit and memory come from, for the log: "computed from
  // the cost model × 3", "from SBATCH_TIMELIMIT" ...; `*_shown` is the value
  // when gridfree passes none itself ("7" of SBATCH_TIMELIMIT=7).
  std::string time_from, time_shown, mem_from, mem_shown;
};

// One log line for the arrays of one submission round: which time limit
// and memory applied and where each came from, e.g. "time limit 00:07:00
// from SBATCH_TIMELIMIT; memory 256M-4096M computed from the cost model × 3".
std::string limits_note(const std::vector<SlurmArray>& arrays);

// Minutes as Slurm's HH:MM:SS ("00:07:00"; days as more hours).
std::string slurm_time_text(double minutes);

// A job with a cores rule (JobLaunch::cores > 0, study/job_cores.h) asks
// Slurm for its own cores: an external code's job as that many tasks of
// one CPU each (its mpirun -np @@cores@@ finds the ranks in the
// allocation), a worker's job as one task of that many CPUs (OpenMP
// threads). Without a rule the shape is left as it is.
void apply_job_cores(SlurmArray& a, const JobLaunch& job);

// Jobs of two shapes may share one array: every directive is the same.
bool same_array_shape(const SlurmArray& a, const SlurmArray& b);

std::string array_script(const std::filesystem::path& worker, const SlurmArray& a,
                         const std::vector<std::string>& setup);

// sbatch --parsable ... SCRIPT
std::vector<std::string> sbatch_command(const SlurmArray& a, const SlurmSettings& s,
                                        const std::filesystem::path& script, const std::filesystem::path& log_dir);

// Single-quotes a word for /bin/sh.
std::string shell_quote(const std::string& word);

// A job name Slurm accepts: printable, no spaces or quotes, at most 100 chars.
std::string slurm_job_name(const std::string& text);

}  // namespace gridfree
