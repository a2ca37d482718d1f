// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/process_run.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace gridfree {
namespace {

// In the child, between fork and exec: only async-signal-safe calls.
[[noreturn]] void exec_child(char* const* argv, int out_fd, int err_fd, int null_fd, bool own_group,
                             const char* cwd) {
  if (own_group) ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int sig : {SIGINT, SIGTERM, SIGPIPE, SIGHUP, SIGCHLD}) ::sigaction(sig, &dfl, nullptr);
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::dup2(null_fd, 0);
  ::dup2(out_fd, 1);
  ::dup2(err_fd, 2);
  if (::chdir(cwd) != 0) ::_exit(126);
  ::execvp(argv[0], argv);
  const int e = errno;
  const char* what = e == ENOENT ? "command not found" : "cannot execute";
  const char* prefix = "gridfree-worker: ";
  (void)!::write(2, prefix, std::strlen(prefix));
  (void)!::write(2, argv[0], std::strlen(argv[0]));
  (void)!::write(2, ": ", 2);
  (void)!::write(2, what, std::strlen(what));
  (void)!::write(2, "\n", 1);
  ::_exit(e == ENOENT ? 127 : 126);
}

int open_log(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
  return fd;
}

}  // namespace

std::vector<std::string> launch_argv(const CommandLaunch& launch) {
  if (launch.setup.empty()) return launch.command;
  std::string script = "set -e\n";
  for (const auto& line : launch.setup) script += line + "\n";
  script += "exec \"$@\"\n";
  std::vector<std::string> argv = {"/bin/sh", "-c", script, "gridfree-setup"};
  argv.insert(argv.end(), launch.command.begin(), launch.command.end());
  return argv;
}

CommandEnd run_command_watched(const CommandLaunch& launch, const CommandWatch& watch) {
  const std::vector<std::string> args = launch_argv(launch);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string cwd = launch.cwd.string();

  const int out_fd = open_log(launch.stdout_file);
  int err_fd = -1;
  try {
    err_fd = open_log(launch.stderr_file);
  } catch (...) {
    ::close(out_fd);
    throw;
  }
  const int null_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  // Leading our own group (the orchestrator's setpgid): the command stays in it.
  const bool own_group = ::getpgrp() != ::getpid();

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) exec_child(argv.data(), out_fd, err_fd, null_fd < 0 ? out_fd : null_fd, own_group, cwd.c_str());
  ::close(out_fd);
  ::close(err_fd);
  if (null_fd >= 0) ::close(null_fd);
  if (pid < 0) throw std::runtime_error(std::string("cannot start the command: ") + std::strerror(errno));
  if (own_group) ::setpgid(pid, pid);  // also from here, so the group exists before we signal it

  const auto signal_command = [&](int sig) {
    if (own_group) ::killpg(pid, sig);
    else ::killpg(::getpgrp(), sig);  // the worker's own group: we only set our stop flag again
  };
  CommandEnd end;
  auto last_tick = start;
  std::optional<std::chrono::steady_clock::time_point> stop_sent;
  bool killed = false;
  for (;;) {
    int status = 0;
    struct rusage ru {};
    const pid_t r = ::wait4(pid, &status, WNOHANG, &ru);
    if (r == pid) {
      if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
      else if (WIFSIGNALED(status)) end.signal = WTERMSIG(status);
      end.cpu_s = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
                  1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
      end.peak_rss_mb = static_cast<double>(ru.ru_maxrss) / 1024.0;
      // A SIGTERM to the whole group reaches the command before we poll the
      // flag: it ended because of the stop, whatever its exit says.
      if (watch.stop_requested && watch.stop_requested()) end.stopped = true;
      break;
    }
    if (r < 0 && errno != EINTR) throw std::runtime_error(std::string("waiting for the command: ") + std::strerror(errno));
    const auto now = std::chrono::steady_clock::now();
    if (watch.stop_requested && watch.stop_requested() && !stop_sent) {
      end.stopped = true;
      stop_sent = now;
      signal_command(SIGTERM);
    }
    if (stop_sent && !killed && now - *stop_sent > std::chrono::duration<double>(watch.stop_grace_s)) {
      killed = true;
      if (own_group) ::killpg(pid, SIGKILL);
      else ::kill(pid, SIGKILL);
    }
    if (watch.on_tick && now - last_tick >= std::chrono::seconds(2)) {
      last_tick = now;
      watch.on_tick(std::chrono::duration<double>(now - start).count());
    }
    const bool early = now - start < std::chrono::seconds(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(early ? 5 : 50));
  }
  end.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Whatever the command left running in its own group goes with it.
  if (own_group) ::killpg(pid, SIGKILL);
  return end;
}

}  // namespace gridfree
