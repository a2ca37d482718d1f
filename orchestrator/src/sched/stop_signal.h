// SPDX-License-Identifier: GPL-3.0-or-later
// SIGINT/SIGTERM → a stop request the scheduler loop polls. The handler
// only sets a sig_atomic_t flag (the one piece of global state); the
// previous handlers are restored when the guard goes away.
#pragma once

#include <csignal>

namespace gridfree {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  bool requested() const;
  int signal_number() const;  // the signal received, 0 if none

 private:
  struct sigaction old_int_ {}, old_term_ {};
};

}  // namespace gridfree
