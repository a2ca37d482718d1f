// Cluster settings of the Slurm executor (docs/ORCHESTRATOR.md, "Slurm
// settings"): read from a profile file (JSON), then overridden field by field
// by command-line flags (profile < flags). Unset fields fall back to the
// defaults below; time and memory default to the plan's cost model
// (study/study_plan.h) times `margin`.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

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
};

// Reads a profile: a JSON object with the fields above (time_minutes,
// mem_mb, cpus_per_task, sbatch_args, setup, runs_dir, max_queued,
// array_size, poll_s, margin, partition, account, qos, constraint). Unknown
// fields and wrong types throw InputError naming the field.
SlurmSettings read_slurm_profile(const std::filesystem::path& file);
SlurmSettings slurm_settings_from_json(const nlohmann::json& j, const std::string& where);

// `over` wins field by field where it is set.
SlurmSettings merge(const SlurmSettings& base, const SlurmSettings& over);

// Throws InputError naming the first out-of-range field ("--mem", ...).
void validate(const SlurmSettings& s);

}  // namespace gridfree
