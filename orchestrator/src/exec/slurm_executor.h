// SPDX-License-Identifier: GPL-3.0-or-later
// Runs jobs as Slurm array tasks (docs/ORCHESTRATOR.md, "Slurm"):
//
//   start()   gathers jobs; flush() groups them by size (cpus, time and
//             memory limits) and submits each group as one
//             `sbatch --array=0-K%N` (N = the -j slots), K <= array_size;
//             while 2N+8 of ours wait in the queue, a refill waits for a
//             tenth of array_size jobs or 5 s (submit_due);
//   poll      one `squeue --me` for all our jobs (an array's waiting tasks
//             on one line), at an interval that adapts
//             to the run times seen (or the profile's poll_s); a finished
//             task is noticed earlier by its <run_dir>/exit_code file;
//   finished  exit code from the exit_code file, else `sacct`, else the
//             result.json the worker left (a purged job), else lost;
//   faults    slurm_faults.h: transient submit failures wait and retry with
//             backoff; a permanent one (sbatch missing, a bad partition)
//             submits nothing more and becomes fatal_error() (no attempt
//             spent); never-startable jobs are refused with Slurm's words;
//   limits    the user's time and memory (settings, sbatch_args, SBATCH_*
//             environment) win over the cost model's; logged once per
//             submission round (limits_note);
//   timeout   counts run time (squeue's TimeUsed), not time in the queue,
//             and becomes `--time` unless the settings give one;
//   adopt()   takes over a task submitted by an earlier (crashed) process,
//             found by its recorded id, or by <run_dir>/slurm_submit (script
//             and task index, written before sbatch) when the id was not
//             recorded yet.
//
// The Slurm commands are found on PATH.
#pragma once

#include <chrono>
#include <deque>
#include <map>

#include "exec/executor.h"
#include "exec/slurm_script.h"
#include "exec/slurm_settings.h"

namespace gridfree {

class SlurmExecutor : public Executor {
 public:
  // `slots` = tasks of one array running at once (the %N throttle).
  SlurmExecutor(std::filesystem::path worker, std::filesystem::path runs_root, SlurmSettings settings = {},
                int slots = 1);
  ~SlurmExecutor() override;

  void start(const JobLaunch& job) override;
  void flush() override;
  std::optional<JobExit> wait_any(double timeout_s) override;
  std::vector<long long> kill_all() override;
  std::size_t in_flight() const override { return tasks_.size() + unsent_.size() + finished_.size(); }
  std::string external_id(long long job_id) const override;
  std::vector<JobUpdate> take_updates() override;
  bool adopt(const JobLaunch& job, const std::string& external_id) override;
  std::optional<std::string> fatal_error() const override { return fatal_; }

  // The poll interval now in effect (seconds).
  double poll_interval() const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Task {
    JobLaunch launch;
    std::string slurm_id;           // "1234_5"
    std::string state = "SUBMITTED", reason;
    double used_s = 0;              // TimeUsed at the last poll
    Clock::time_point polled_at{};  // when used_s was read
    bool adopted = false;
    bool seen = false;              // listed by squeue at least once
  };
  void submit_unsent();
  bool submit_due() const;  // the gathered jobs go to sbatch now
  void submit_group(const std::vector<JobLaunch>& group, const SlurmArray& shape);
  void poll();
  void check_exit_files();
  void finish(std::map<long long, Task>::iterator it, JobExit e);
  JobExit exit_of(const Task& t);
  SlurmArray shape_of(const JobLaunch& job) const;
  void note(const Task& t);
  // The Slurm id of a job submitted but not recorded (its run folder's
  // slurm_submit file matched against squeue's commands); "unrecorded" when
  // it already ended, leaving an exit code or result; nullopt if not found.
  std::optional<std::string> find_unrecorded(const JobLaunch& job);

  std::filesystem::path worker_, runs_root_;
  SlurmSettings settings_;
  int slots_;
  std::vector<JobLaunch> unsent_;            // gathered, or waiting out a transient fault
  Clock::time_point gathered_at_{};          // when the oldest of unsent_ was gathered
  int running_now_ = 0;                      // tasks_ RUNNING or COMPLETING as last polled
  Clock::time_point retry_at_{};
  double backoff_s_ = 0;
  Clock::time_point last_poll_{}, last_file_check_{};
  double mean_run_s_ = 0;                    // run time of finished tasks (running mean)
  int runs_seen_ = 0;
  std::map<long long, Task> tasks_;          // by gridfree job id
  std::deque<JobExit> finished_;
  std::vector<JobUpdate> updates_;
  int array_counter_ = 0;
  std::optional<std::string> fatal_;         // a permanent submit failure: nothing more is submitted
};

}  // namespace gridfree
