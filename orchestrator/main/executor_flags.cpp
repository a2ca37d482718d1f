// SPDX-License-Identifier: GPL-3.0-or-later
// --executor and Slurm flags (see executor_flags.h).
#include "executor_flags.h"

#include "core/input_error.h"
#include "exec/local_executor.h"
#include "exec/program_path.h"
#include "exec/slurm_executor.h"
#include "exec/worker_path.h"

namespace gridfree::cli {

void add_executor_flags(CLI::App* sub, ExecutorFlags& f) {
  sub->add_option("--executor", f.kind, "where jobs run: local (this machine) or slurm (sbatch)")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  // The Slurm flags under their own heading of `help run` (local runs ignore them).
  constexpr const char* kSlurmGroup = "Slurm (--executor slurm only)";
  sub->add_option("--slurm-profile", f.profile, "Slurm settings (JSON file); the flags below override it")
      ->group(kSlurmGroup);
  sub->add_option("--partition", f.slurm.partition, "Slurm partition")
      ->group(kSlurmGroup);
  sub->add_option("--account", f.slurm.account, "Slurm account")
      ->group(kSlurmGroup);
  sub->add_option("--qos", f.slurm.qos, "Slurm QOS")
      ->group(kSlurmGroup);
  sub->add_option("--constraint", f.slurm.constraint, "Slurm node constraint")
      ->group(kSlurmGroup);
  sub->add_option("--time", f.slurm.time_minutes, "Slurm time limit per job, minutes (default: cost model x margin)")
      ->group(kSlurmGroup);
  sub->add_option("--mem", f.slurm.mem_mb, "Slurm memory per job, MB (default: cost model x margin)")
      ->group(kSlurmGroup);
  sub->add_option("--cpus-per-task", f.slurm.cpus_per_task, "Slurm CPUs per job = worker threads (default 1)")
      ->group(kSlurmGroup);
  sub->add_option("--sbatch-arg", f.slurm.sbatch_args, "extra sbatch argument (repeatable)")
      ->group(kSlurmGroup);
  sub->add_option("--setup", f.slurm.setup, "shell line run before the worker, e.g. 'module load gcc' (repeatable)")
      ->group(kSlurmGroup);
  sub->add_option("--runs-dir", f.slurm.runs_dir, "run folders on storage the nodes share (default <db>.runs)")
      ->group(kSlurmGroup);
  sub->add_option("--max-queued", f.slurm.max_queued, "most jobs of this study in the Slurm queue (default 1000)")
      ->group(kSlurmGroup);
  sub->add_option("--array-size", f.slurm.array_size, "most jobs in one Slurm array (default 1000; 1 = no arrays)")
      ->group(kSlurmGroup);
  sub->add_option("--poll", f.slurm.poll_s, "squeue interval, seconds (default: adapts to run times)")
      ->group(kSlurmGroup);
  sub->add_option("--margin", f.margin, "cost-model estimate x margin = default --time/--mem (default 3)")
      ->group(kSlurmGroup);
}

namespace {

// The first Slurm flag given ("" if none): refused with the local executor.
std::string first_slurm_flag(const ExecutorFlags& f) {
  const SlurmSettings& s = f.slurm;
  if (!f.profile.empty()) return "--slurm-profile";
  if (!s.partition.empty()) return "--partition";
  if (!s.account.empty()) return "--account";
  if (!s.qos.empty()) return "--qos";
  if (!s.constraint.empty()) return "--constraint";
  if (s.time_minutes) return "--time";
  if (s.mem_mb) return "--mem";
  if (s.cpus_per_task) return "--cpus-per-task";
  if (!s.sbatch_args.empty()) return "--sbatch-arg";
  if (!s.setup.empty()) return "--setup";
  if (!s.runs_dir.empty()) return "--runs-dir";
  if (s.max_queued) return "--max-queued";
  if (s.array_size) return "--array-size";
  if (s.poll_s) return "--poll";
  if (f.margin != 0) return "--margin";
  return "";
}

}  // namespace

std::unique_ptr<Executor> make_executor(const ExecutorFlags& f, const std::string& db, int jobs,
                                        SchedulerOptions& options, const nlohmann::json* study_slurm,
                                        const EnvLookup& env) {
  const auto worker = default_worker_path();
  if (f.kind == "local") {
    if (const auto flag = first_slurm_flag(f); !flag.empty()) throw InputError(flag, "only with --executor slurm");
    std::error_code ec;
    if (!std::filesystem::exists(worker, ec))
      throw std::runtime_error("worker executable not found: " + worker.string() + " (set GRIDFREE_WORKER)");
    return std::make_unique<LocalExecutor>(worker);
  }
  if (f.kind != "slurm") throw InputError("--executor", "unknown executor '" + f.kind + "'; valid: local, slurm");
  SlurmSettings s = f.profile.empty() ? SlurmSettings{} : read_slurm_profile(f.profile);
  if (study_slurm != nullptr) s = merge(s, slurm_settings_from_json(*study_slurm, "/slurm"));
  SlurmSettings flags = f.slurm;
  if (f.margin != 0) flags.margin = f.margin;
  s = merge(s, flags);
  s.environment = sbatch_environment(env);  // below every setting, above the computed defaults
  validate(s);
  // A missing Slurm command is a configuration error: refused (after the
  // settings, which need no cluster) before the database is opened, so no
  // job is claimed, submitted or failed.
  const std::string path = env("PATH").value_or("");
  if (const auto missing = missing_programs(kSlurmRequiredPrograms, path); !missing.empty()) {
    std::string names;
    for (const auto& m : missing) names += (names.empty() ? "'" : ", '") + m + "'";
    throw InputError("--executor", "slurm needs " + names + " on PATH, which does not have " +
                                       (missing.size() == 1 ? "it" : "them") + " (PATH=" + path +
                                       "); load the cluster's Slurm module or fix PATH");
  }
  auto runs = s.runs_dir.empty() ? runs_root_for(db) : std::filesystem::absolute(s.runs_dir);
  options.runs_root = runs;
  options.workers = s.max_queued.value_or(1000);
  options.threads_per_job = s.cpus_per_task.value_or(1);
  options.cores = 0;  // Slurm places the jobs; a cores rule is capped by --cpus-per-task
  return std::make_unique<SlurmExecutor>(worker, runs, s, jobs);
}

}  // namespace gridfree::cli
