// SPDX-License-Identifier: GPL-3.0-or-later
// The seam between the scheduler and wherever jobs run (ninja's
// CommandRunner): start a job, wait for any one to finish, kill them all.
// Implementations: LocalExecutor (child processes), SlurmExecutor (sbatch),
// and a fake in the tests.
#pragma once

#include <cstddef>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct JobLaunch {
  long long job_id = 0;
  std::string job_hash;
  std::filesystem::path run_dir;   // holds job.json; result.json and worker.log go here
  int threads = 1;                 // --threads for the worker
  // The cores the study's cores rule gives the job (study/job_cores.h; then
  // threads == cores, and an external template's @@cores@@); 0 = no rule.
  int cores = 0;
  double timeout_s = 0;            // 0 = none
  // The worker is created but does not run until release(job_id): the caller
  // records external_id() first, so no worker runs that a restart could not
  // find. If the caller dies before releasing, the worker never runs.
  bool hold = false;
  std::string name;                // for people: study, series, grid (Slurm job name)
  std::array<int, 3> cells{};      // grid size (cost-model estimates)
  // The job's kind has its own cost estimate (study/case_kind.h own_cost;
  // an external code, docs/EXTERNAL.md "Cost"): gridfree's cost model does
  // not describe it, so executors use the scheduler's estimate instead:
  // memory_bytes (NaN: unknown) and where it comes from.
  bool own_estimate = false;
  // Its cores are MPI tasks, not threads of one process (study/case_kind.h).
  bool cores_are_tasks = false;
  double memory_bytes = NAN;
  std::string memory_basis;
  // The worker's --bed-cache folder (bed_cache_dir); empty = none.
  std::filesystem::path bed_cache;
};

// A job's state in an external queue, for `status` (Slurm: id, state, reason).
struct JobUpdate {
  long long job_id = 0;
  std::string external_id;         // "slurm:1234_5"
  std::string state, reason;       // PENDING / Priority, RUNNING / None, ...
};

struct JobExit {
  // kRefused: the cluster will never start it (a pending Reason such as
  // PartitionTimeLimit: a limit the job exceeds): final. kVanished: gone without a trace while nobody watched
  // (adopted after a restart): run again without spending an attempt.
  enum class How { kExited, kSignaled, kTimedOut, kKilled, kLaunchFailed, kLost, kRefused, kVanished };
  long long job_id = 0;
  How how = How::kExited;
  int code = 0;                    // exit code (kExited; kTimedOut when the worker exited by itself)
  int signal = 0;                  // kSignaled
  std::string detail;              // what happened, in words
  std::filesystem::path run_dir;
  double wall_s = 0;
};

std::string describe(const JobExit& e);  // "exit 3", "killed by signal 11 (SIGSEGV)", ...

class Executor {
 public:
  virtual ~Executor() = default;
  // Starts a job; a launch failure comes back from wait_any as kLaunchFailed.
  virtual void start(const JobLaunch& job) = 0;
  // Waits up to timeout_s for one job to finish; nullopt when none did.
  virtual std::optional<JobExit> wait_any(double timeout_s) = 0;
  // Kills every job in flight (their process groups / cancels them), reaps
  // them and returns their ids.
  virtual std::vector<long long> kill_all() = 0;
  virtual std::size_t in_flight() const = 0;
  // An id that can be used to find or kill the job after a restart ("" if none).
  virtual std::string external_id(long long job_id) const = 0;
  // Lets a job started with `hold` run (no-op for executors that cannot hold).
  virtual void release(long long /*job_id*/) {}
  // Submits what start() has gathered (executors that batch jobs, such as
  // Slurm arrays); called after a round of start()s.
  virtual void flush() {}
  // Ids assigned and queue states changed since the last call.
  virtual std::vector<JobUpdate> take_updates() { return {}; }
  // Takes over a job started by an earlier process from its external id;
  // false when this executor cannot (then the job is requeued).
  virtual bool adopt(const JobLaunch& /*job*/, const std::string& /*external_id*/) { return false; }
  // Set when the executor can run nothing more (sbatch refused a submission
  // for a reason no retry changes): the caller stops the loop, which
  // requeues the jobs in flight without spending an attempt, and exits 2
  // with this message.
  virtual std::optional<std::string> fatal_error() const { return std::nullopt; }
};

// The worker command line (docs/INTERFACE.md §2) for a run directory:
// result, progress and checkpoint files in it; the worker resumes from the
// checkpoint when one is there (a stop or timeout left it); generated beds
// go through `bed_cache` unless it is empty.
std::vector<std::string> worker_command(const std::filesystem::path& worker, const std::filesystem::path& run_dir,
                                        int threads, const std::filesystem::path& bed_cache = {});

// Where the workers of a database keep generated beds: <runs_root>/beds
// (worker/src/job/bed_cache.h; safe to delete between runs).
std::filesystem::path bed_cache_dir(const std::filesystem::path& runs_root);

// A job's run folder: <runs_root>/<first two hex digits of its hash>/<hash>
// (256 shards: 50 000 jobs make about 200 entries per folder, not 50 000
// in one), or <runs_root>/<hash> when that folder of the flat layout of
// older versions exists (so a resume finds the checkpoint it left there).
// A hash that is empty or not a plain file name: <runs_root>/<hash>.
std::filesystem::path run_dir_for(const std::filesystem::path& runs_root, const std::string& job_hash);

// run_dir_for(runs_root, job_hash) with job.json written (atomically) and
// any old result.json removed.
std::filesystem::path prepare_run_dir(const std::filesystem::path& runs_root, const std::string& job_hash,
                                      const std::string& job_json);

// <run_dir>/checkpoint.bin: where a worker asked to stop writes its state.
std::filesystem::path checkpoint_file(const std::filesystem::path& run_dir);

// Removes a job's checkpoint once its result is committed (no error if none).
void remove_checkpoint(const std::filesystem::path& run_dir);

// Seconds a worker has, after SIGTERM (a timeout, a shutdown), to finish
// its outer iteration and write its checkpoint before SIGKILL.
inline constexpr double kStopGraceSeconds = 30.0;

// "<db file>.runs" beside the database.
std::filesystem::path runs_root_for(const std::filesystem::path& db_file);

// Last `lines` lines of a text file (for error messages), "" if unreadable.
std::string tail_of_file(const std::filesystem::path& file, int lines = 5);

}  // namespace gridfree
