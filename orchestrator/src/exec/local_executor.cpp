// SPDX-License-Identifier: GPL-3.0-or-later
// LocalExecutor: posix_spawn + process groups + waitpid polling (see local_executor.h).
#include "exec/local_executor.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "core/process_identity.h"
#include "exec/exit_notice.h"
#include "exec/worker_progress.h"

extern char** environ;

namespace gridfree {

std::string process_identity(pid_t pid) {
  return process_identity_string(pid);
}

bool kill_process_group_if_alive(const std::string& identity) {
  const auto a = identity.find(':');
  const auto b = identity.find(':', a == std::string::npos ? 0 : a + 1);
  if (a == std::string::npos || b == std::string::npos || identity.substr(0, a) != host_name()) return false;
  long pid = 0;
  try {
    pid = std::stol(identity.substr(a + 1, b - a - 1));
  } catch (...) {
    return false;
  }
  const std::string started = identity.substr(b + 1);
  if (pid <= 1 || started.empty() || process_start_time(pid) != started) return false;
  return killpg(static_cast<pid_t>(pid), SIGKILL) == 0;
}

LocalExecutor::~LocalExecutor() { kill_all(); }

namespace {

// A held worker waits in /bin/sh for the orchestrator's one byte on fd 3
// (the gate's read end), then replaces the shell by the worker: same pid,
// same start time. At EOF without the byte (the orchestrator is gone) the
// shell exits 0 and the worker never runs. `read` returns non-zero at EOF
// even after reading "x" (no newline), so the byte itself is tested.
constexpr const char* kGateScript = "IFS= read -r go <&3; [ \"$go\" = x ] || exit 0; exec 3<&- \"$@\"";

// posix_spawn (no copy of the orchestrator's page tables, whose size grows
// with the study: fork's copy and copy-on-write faults were most of the
// orchestrator's CPU per job at 50 000 jobs, docs/BENCHMARKS.md) of argv in
// its own process group, stdin /dev/null, stdout+stderr to `log`, default
// signal dispositions and an empty mask. gate_read >= 0: through
// kGateScript, the gate on fd 3. Returns the pid, or -errno.
pid_t spawn_worker(const std::vector<char*>& argv, const std::string& log, int gate_read) {
  std::string sh = "/bin/sh", dash_c = "-c", script = kGateScript, name = "gridfree-held";
  std::vector<char*> args;
  if (gate_read >= 0) args = {sh.data(), dash_c.data(), script.data(), name.data()};
  args.insert(args.end(), argv.begin(), argv.end());  // argv ends with nullptr
  posix_spawn_file_actions_t fa;
  posix_spawnattr_t attr;
  posix_spawn_file_actions_init(&fa);
  posix_spawnattr_init(&attr);
  posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
  if (gate_read >= 0) posix_spawn_file_actions_adddup2(&fa, gate_read, 3);  // dup2 clears FD_CLOEXEC
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGINT, SIGTERM, SIGPIPE, SIGHUP, SIGCHLD}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setpgroup(&attr, 0);  // its own process group, led by the worker
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &fa, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  return rc == 0 ? pid : -rc;
}

}  // namespace

void LocalExecutor::release(long long job_id) {
  for (auto& [pid, c] : running_) {
    if (c.job_id != job_id || c.gate < 0) continue;
    const char go = 'x';
    ssize_t n = 0;
    do n = ::write(c.gate, &go, 1);
    while (n < 0 && errno == EINTR);
    ::close(c.gate);
    c.gate = -1;
  }
}

void LocalExecutor::start(const JobLaunch& job) {
  const auto argv_s = worker_command(worker_, job.run_dir, job.threads, job.bed_cache);
  std::vector<char*> argv;
  for (const auto& a : argv_s) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string log = (job.run_dir / "worker.log").string();
  JobExit failed;
  failed.job_id = job.job_id;
  failed.how = JobExit::How::kLaunchFailed;
  failed.run_dir = job.run_dir;
  int gate[2] = {-1, -1};
  if (job.hold) {
    // Held: the shell would only report a missing worker once released.
    if (::access(argv[0], X_OK) != 0) {
      failed.detail = worker_.string() + ": " + std::strerror(errno);
      failed_launches_.push_back(std::move(failed));
      return;
    }
    if (::pipe2(gate, O_CLOEXEC) != 0) {
      failed.detail = std::string("pipe: ") + std::strerror(errno);
      failed_launches_.push_back(std::move(failed));
      return;
    }
  }
  const pid_t pid = spawn_worker(argv, log, gate[0]);
  if (gate[0] >= 0) ::close(gate[0]);
  if (pid < 0) {
    if (gate[1] >= 0) ::close(gate[1]);
    failed.detail = worker_.string() + ": " + std::strerror(-pid);
    failed_launches_.push_back(std::move(failed));
    return;
  }
  Child c;
  c.job_id = job.job_id;
  c.run_dir = job.run_dir;
  c.started = Clock::now();
  c.timeout_s = job.timeout_s;
  c.launch_grace_s = stop_grace_for_run(job.run_dir, stop_grace_s_);
  c.gate = gate[1];
  c.exit_notice = open_exit_notice(pid);
  if (job.timeout_s > 0)
    c.deadline = c.started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(job.timeout_s));
  running_[pid] = std::move(c);
}

std::string LocalExecutor::external_id(long long job_id) const {
  for (const auto& [pid, c] : running_)
    if (c.job_id == job_id) return "local:" + process_identity(pid);
  return "";
}

// The larger of what the current attempt's progress file says and what an
// earlier attempt's said at launch (a resumed worker reports its iteration
// time only from its second iteration on).
LocalExecutor::Clock::duration LocalExecutor::grace_for(const Child& c) const {
  const double s = std::max(c.launch_grace_s, stop_grace_for_run(c.run_dir, stop_grace_s_));
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// Timeout: SIGTERM to the group (the worker checkpoints), SIGKILL after the
// grace period, which grows with the worker's longest outer iteration.
void LocalExecutor::enforce_deadlines() {
  const auto now = Clock::now();
  for (auto& [pid, c] : running_) {
    if (!c.timed_out && c.deadline && now >= *c.deadline) {
      killpg(pid, SIGTERM);
      c.timed_out = true;
      c.kill_at = now + grace_for(c);
    } else if (c.kill_at && now >= *c.kill_at) {
      killpg(pid, SIGKILL);
      c.kill_at.reset();
    }
  }
}

namespace {

// The worker exited by itself with a result (0 converged, 3 not converged):
// when that happens after our timeout's SIGTERM, it had finished before the
// stop reached it, and its result stands (a finished result is never lost).
bool finished_normally(int status) {
  return WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 3);
}

}  // namespace

std::optional<JobExit> LocalExecutor::reap_one() {
  for (auto it = running_.begin(); it != running_.end(); ++it) {
    int status = 0;
    const pid_t r = waitpid(it->first, &status, WNOHANG);
    if (r == 0) continue;
    JobExit e;
    e.job_id = it->second.job_id;
    e.run_dir = it->second.run_dir;
    e.wall_s = std::chrono::duration<double>(Clock::now() - it->second.started).count();
    if (r < 0) {
      e.how = JobExit::How::kLost;
      e.detail = std::strerror(errno);
    } else if (it->second.timed_out && !finished_normally(status)) {
      e.how = JobExit::How::kTimedOut;
      char after[64];
      std::snprintf(after, sizeof after, "no result after %g s", it->second.timeout_s);
      e.detail = after;
      if (WIFEXITED(status)) e.code = WEXITSTATUS(status);  // 130: stopped with a checkpoint
    } else if (WIFEXITED(status)) {
      e.how = JobExit::How::kExited;
      e.code = WEXITSTATUS(status);
    } else {
      e.how = JobExit::How::kSignaled;
      e.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    // Anything the worker left in its group goes with it.
    killpg(it->first, SIGKILL);
    if (it->second.gate >= 0) ::close(it->second.gate);
    if (it->second.exit_notice >= 0) ::close(it->second.exit_notice);
    running_.erase(it);
    return e;
  }
  return std::nullopt;
}

std::optional<JobExit> LocalExecutor::wait_any(double timeout_s) {
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  for (;;) {
    if (!failed_launches_.empty()) {
      JobExit e = std::move(failed_launches_.front());
      failed_launches_.erase(failed_launches_.begin());
      return e;
    }
    enforce_deadlines();
    if (auto e = reap_one()) return e;
    const auto now = Clock::now();
    if (running_.empty() || now >= until) return std::nullopt;
    std::vector<int> notices;
    for (const auto& [pid, c] : running_) notices.push_back(c.exit_notice);
    // Every 20 ms at least (deadlines), at once when a worker exits.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - now);
    wait_for_exit_notice(notices, std::min(left, std::chrono::milliseconds(20)));
  }
}

// Shutdown: SIGTERM to every running worker (each writes its checkpoint),
// then SIGKILL to whatever is left after its grace period.
std::vector<long long> LocalExecutor::kill_all() {
  std::vector<long long> ids;
  const auto now = Clock::now();
  std::map<pid_t, Clock::time_point> until;
  for (auto& [pid, c] : running_) {
    if (c.gate >= 0) {  // held: never ran; exits on the closed pipe
      ::close(c.gate);
      c.gate = -1;
      killpg(pid, SIGKILL);
      until[pid] = now;
      continue;
    }
    killpg(pid, SIGTERM);
    const auto grace = grace_for(c);
    until[pid] = now + grace;
    const double grace_s = std::chrono::duration<double>(grace).count();
    if (grace_s > stop_grace_s_ + 1)
      spdlog::info("job {}: waiting up to {:.0f} s for its worker to finish the outer iteration and write a checkpoint",
                   c.job_id, grace_s);
  }
  // All at once: each worker is killed at its own deadline, not after the
  // ones before it have ended.
  while (!until.empty()) {
    for (auto it = until.begin(); it != until.end();) {
      int status = 0;
      const pid_t pid = it->first;
      bool ended = waitpid(pid, &status, WNOHANG) != 0;
      if (!ended && Clock::now() >= it->second) {
        killpg(pid, SIGKILL);
        waitpid(pid, &status, 0);
        ended = true;
      }
      if (!ended) {
        ++it;
        continue;
      }
      killpg(pid, SIGKILL);  // anything the worker left in its group
      ids.push_back(running_.at(pid).job_id);
      it = until.erase(it);
    }
    if (!until.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (const auto& [pid, c] : running_)
    if (c.exit_notice >= 0) ::close(c.exit_notice);
  running_.clear();
  for (const auto& e : failed_launches_) ids.push_back(e.job_id);
  failed_launches_.clear();
  return ids;
}

}  // namespace gridfree
