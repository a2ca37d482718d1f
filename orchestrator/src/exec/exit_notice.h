// SPDX-License-Identifier: GPL-3.0-or-later
// Waiting for a child's exit without polling on a timer: a pidfd per child
// (Linux ≥ 5.3) becomes readable when the child terminates, so the
// scheduler's wait wakes as soon as a worker ends instead of at its next
// 20 ms tick (with workers that finish in milliseconds, the tick was most
// of the time per job: docs/BENCHMARKS.md). Where pidfds are not available
// the wait is the plain sleep it replaces.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <vector>

namespace gridfree {

// A pidfd for `pid` (close-on-exec), or -1 when the kernel has none.
int open_exit_notice(pid_t pid);

// Sleeps up to `at_most`, returning early when a process behind one of
// `notices` has exited. Any -1 among them (a child without a pidfd), or
// none at all: the full sleep, as before pidfds.
void wait_for_exit_notice(const std::vector<int>& notices, std::chrono::milliseconds at_most);

}  // namespace gridfree
