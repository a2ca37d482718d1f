// SPDX-License-Identifier: GPL-3.0-or-later
// Polling for a condition that another process makes true.
#pragma once

#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <chrono>
#include <functional>
#include <thread>

namespace gridfree::test_support {

// Whether `done` became true within `limit_s` seconds (asked every 50 ms).
inline bool wait_until(const std::function<bool()>& done, double limit_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (std::chrono::steady_clock::now() < until) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

// The exit code of child `pid` once it has ended, waiting at most `limit_s`
// seconds; -1 when it did not end normally in time (it is then killed and
// reaped).
inline int exit_code_within(pid_t pid, double limit_s) {
  int status = 0;
  if (!wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, limit_s)) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace gridfree::test_support
