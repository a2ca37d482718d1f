// SPDX-License-Identifier: GPL-3.0-or-later
// Runs workers as child processes on this machine. Each worker gets its own
// process group (so a timeout or shutdown kills it and anything it started,
// and a terminal's Ctrl-C reaches only the orchestrator), stdin from
// /dev/null, stdout+stderr into <run_dir>/worker.log. Finished children are
// found by waitpid(WNOHANG), checked every 20 ms (deadlines) and as soon as
// a child's pidfd says it exited (exec/exit_notice.h). A timeout or a shutdown sends SIGTERM to
// the whole group (the worker writes a checkpoint and exits 130) and SIGKILL
// after the grace period: stop_grace_s (kStopGraceSeconds) plus 1.5 × the
// worker's longest outer iteration so far (exec/worker_progress.h).
//
// A held launch (JobLaunch::hold) starts /bin/sh in the worker's process
// group, blocked reading a pipe from the orchestrator; release() writes one
// byte and the shell execs the worker (same pid, same start time, so the
// recorded identity stays valid). If the orchestrator dies first, the pipe
// closes and the shell exits without running the worker. Every launch is a
// posix_spawn: a fork would copy the orchestrator's page tables, whose size
// grows with the study.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "exec/executor.h"

namespace gridfree {

class LocalExecutor : public Executor {
 public:
  explicit LocalExecutor(std::filesystem::path worker, double stop_grace_s = kStopGraceSeconds)
      : worker_(std::move(worker)), stop_grace_s_(stop_grace_s) {}
  ~LocalExecutor() override;

  void start(const JobLaunch& job) override;
  std::optional<JobExit> wait_any(double timeout_s) override;
  std::vector<long long> kill_all() override;
  std::size_t in_flight() const override { return running_.size() + failed_launches_.size(); }
  std::string external_id(long long job_id) const override;
  void release(long long job_id) override;

 private:
  using Clock = std::chrono::steady_clock;
  struct Child {
    long long job_id = 0;
    std::filesystem::path run_dir;
    Clock::time_point started;
    std::optional<Clock::time_point> deadline;
    double timeout_s = 0;
    bool timed_out = false;
    std::optional<Clock::time_point> kill_at;  // SIGTERM sent: SIGKILL then
    double launch_grace_s = 0;  // from the progress file an earlier attempt left
    int gate = -1;  // write end of the hold pipe until released
    int exit_notice = -1;  // its pidfd (exec/exit_notice.h), -1 without
  };
  std::optional<JobExit> reap_one();
  Clock::duration grace_for(const Child& c) const;
  void enforce_deadlines();

  std::filesystem::path worker_;
  double stop_grace_s_ = kStopGraceSeconds;
  std::map<pid_t, Child> running_;
  std::vector<JobExit> failed_launches_;
};

// "host:pid:starttime" of a process (same format as a store owner).
std::string process_identity(pid_t pid);

// Kills the process group led by the process named by `identity` if that
// exact process (same start time) still runs on this host. True if killed.
bool kill_process_group_if_alive(const std::string& identity);

}  // namespace gridfree
