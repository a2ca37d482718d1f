// Runs each job as a Slurm batch job: writes <run_dir>/job.sbatch (the same
// worker command as LocalExecutor, its exit code saved to <run_dir>/exit_code),
// submits with `sbatch --parsable`, watches `squeue`, and once a job has left
// the queue takes its exit code from the exit_code file, else from `sacct`.
// A per-job timeout becomes both `#SBATCH --time` and an `scancel` here.
// The sbatch/squeue/sacct/scancel commands are found on PATH (tests put
// fakes there).
#pragma once

#include <chrono>
#include <map>

#include "exec/executor.h"

namespace gridfree {

class SlurmExecutor : public Executor {
 public:
  SlurmExecutor(std::filesystem::path worker, std::filesystem::path runs_root, double poll_interval_s = 5.0);
  ~SlurmExecutor() override;

  void start(const JobLaunch& job) override;
  std::optional<JobExit> wait_any(double timeout_s) override;
  std::vector<long long> kill_all() override;
  std::size_t in_flight() const override { return jobs_.size() + finished_.size(); }
  std::string external_id(long long job_id) const override;

 private:
  using Clock = std::chrono::steady_clock;
  struct SlurmJob {
    long long job_id = 0;
    std::string slurm_id;
    std::filesystem::path run_dir;
    Clock::time_point started;
    double timeout_s = 0;
  };
  void poll();
  JobExit exit_of(const SlurmJob& j, bool timed_out);

  std::filesystem::path worker_, runs_root_;
  double poll_interval_s_;
  Clock::time_point last_poll_{};
  std::map<long long, SlurmJob> jobs_;   // by gridfree job id
  std::vector<JobExit> finished_;
};

// The batch script for a job (exposed for tests).
std::string sbatch_script(const std::filesystem::path& worker, const JobLaunch& job);

// Runs a shell command, returns (exit status, stdout).
std::pair<int, std::string> run_capture(const std::string& command);

// Single-quotes a word for /bin/sh.
std::string shell_quote(const std::string& word);

}  // namespace gridfree
