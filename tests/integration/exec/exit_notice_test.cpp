// SPDX-License-Identifier: GPL-3.0-or-later
// Exit notices (exec/exit_notice.h): a child's pidfd is readable once the
// child has exited, not before, so the executor's wait can sleep on it.
#include <gtest/gtest.h>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>


#include "exec/exit_notice.h"

namespace gridfree {
namespace {

bool readable(int fd) {
  pollfd p{fd, POLLIN, 0};
  return ::poll(&p, 1, 0) == 1 && (p.revents & POLLIN) != 0;
}

TEST(ExitNotice, ReadableOnceTheChildHasExitedNotBefore) {
  int gate[2];
  ASSERT_EQ(::pipe(gate), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {  // waits for the parent's byte, then exits
    ::close(gate[1]);
    char c = 0;
    const ssize_t n = ::read(gate[0], &c, 1);
    ::_exit(n == 1 ? 0 : 1);
  }
  ::close(gate[0]);
  const int fd = open_exit_notice(pid);
  if (fd < 0) {  // a kernel without pidfds: the executor sleeps as before
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    GTEST_SKIP() << "no pidfd_open on this kernel";
  }
  EXPECT_FALSE(readable(fd));  // blocked on the pipe: alive
  const char go = 'x';
  ASSERT_EQ(::write(gate[1], &go, 1), 1);
  siginfo_t info{};
  ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT), 0);  // exited, not reaped
  EXPECT_TRUE(readable(fd));
  int status = 0;
  EXPECT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  ::close(fd);
  ::close(gate[1]);
}

TEST(ExitNotice, NoPidfdMeansNoNotice) {
  EXPECT_EQ(open_exit_notice(-1), -1);
}

}  // namespace
}  // namespace gridfree
