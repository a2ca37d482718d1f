// SPDX-License-Identifier: GPL-3.0-or-later
// pidfd exit notices (see exit_notice.h).
#include "exec/exit_notice.h"

#include <poll.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

namespace gridfree {

int open_exit_notice(pid_t pid) {
#ifdef SYS_pidfd_open
  const long fd = ::syscall(SYS_pidfd_open, pid, 0);  // pidfds are close-on-exec
  return fd >= 0 ? static_cast<int>(fd) : -1;
#else
  (void)pid;
  return -1;
#endif
}

void wait_for_exit_notice(const std::vector<int>& notices, std::chrono::milliseconds at_most) {
  if (at_most.count() <= 0) return;
  const bool all = !notices.empty() && std::none_of(notices.begin(), notices.end(), [](int fd) { return fd < 0; });
  if (!all) {
    std::this_thread::sleep_for(at_most);
    return;
  }
  std::vector<pollfd> fds;
  for (int fd : notices) fds.push_back({fd, POLLIN, 0});
  // EINTR (a stop signal) returns early too: the caller checks and waits again.
  ::poll(fds.data(), fds.size(), static_cast<int>(at_most.count()));
}

}  // namespace gridfree
