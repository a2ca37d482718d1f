// SPDX-License-Identifier: GPL-3.0-or-later
// Cluster settings of the Slurm executor (docs/ORCHESTRATOR.md, "Slurm
// settings"): read from a profile file (JSON), then overridden field by field
// by the study's "slurm" block and command-line flags (profile < study <
// flags). Unset fields fall back to the defaults below; time and memory
// default to the plan's cost model (study/study_plan.h) times `margin`,
// unless the user set them some other way: in sbatch_args, or in sbatch's
// own input environment (SBATCH_TIMELIMIT, SBATCH_MEM_PER_NODE, ...), which
// sbatch reads itself once gridfree passes no value of its own.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

// One environment variable as set: name and value.
struct EnvSetting {
  std::string name, value;
};

// What the user's environment sets among the sbatch input variables that
// overlap gridfree's own settings (sbatch's man page, "INPUT ENVIRONMENT
// VARIABLES"). sbatch gives its command line precedence over them, so
// gridfree passes no --time or --mem of its own when they are set.
struct SbatchEnvironment {
  std::optional<EnvSetting> time;    // SBATCH_TIMELIMIT
  std::optional<EnvSetting> memory;  // SBATCH_MEM_PER_NODE, SBATCH_MEM_PER_CPU or SBATCH_MEM_PER_GPU
  // SBATCH_PARTITION, SBATCH_ACCOUNT, SBATCH_QOS, SBATCH_CONSTRAINT: sbatch
  // reads them when the settings give no value (named in the log).
  std::vector<EnvSetting> others;
};

// Looks up an environment variable (nullopt = unset); a value, so that tests
// pass their own environment.
using EnvLookup = std::function<std::optional<std::string>(const std::string& name)>;
EnvLookup process_environment();  // getenv
SbatchEnvironment sbatch_environment(const EnvLookup& env);

// Minutes of a Slurm time string ("7", "MM:SS", "HH:MM:SS", "D-HH",
// "D-HH:MM", "D-HH:MM:SS"); nullopt if it is none of them ("UNLIMITED").
std::optional<double> slurm_time_minutes(const std::string& text);

struct SlurmSettings {
  std::string partition, account, qos, constraint;  // "" = cluster default
  std::optional<double> time_minutes;   // --time; default: cost model × margin (or --timeout)
  std::optional<double> mem_mb;         // --mem; default: cost model × margin
  std::optional<int> cpus_per_task;     // default: the worker's --threads
  std::vector<std::string> sbatch_args; // appended to sbatch's command line as given
  std::vector<std::string> setup;       // shell lines run before the worker (module load ...)
  std::filesystem::path runs_dir;       // run folders (shared storage); default <db>.runs
  std::optional<int> max_queued;        // jobs of ours in the queue at once; default 1000
  std::optional<int> array_size;        // most tasks in one array; default 1000 (1 = no arrays)
  std::optional<double> poll_s;         // squeue interval; default: adaptive (0.5..30 s)
  double margin = 3.0;                  // cost-model estimate × margin = default time/memory
  SbatchEnvironment environment;        // below every setting above, above the computed defaults
};

// Reads a profile: a JSON object with the fields above (time_minutes,
// mem_mb, cpus_per_task, sbatch_args, setup, runs_dir, max_queued,
// array_size, poll_s, margin, partition, account, qos, constraint). Unknown
// fields and wrong types throw InputError naming the field.
SlurmSettings read_slurm_profile(const std::filesystem::path& file);
SlurmSettings slurm_settings_from_json(const nlohmann::json& j, const std::string& where);

// `over` wins field by field where it is set (`environment` is base's).
SlurmSettings merge(const SlurmSettings& base, const SlurmSettings& over);

// Throws InputError naming the first out-of-range field ("--mem", ...).
void validate(const SlurmSettings& s);

}  // namespace gridfree
