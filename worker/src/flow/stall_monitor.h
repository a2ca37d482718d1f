// SPDX-License-Identifier: GPL-3.0-or-later
// Whether outer iterations have stalled: a limit cycle just above the
// steady tolerance, which more iterations do not break. Always on the
// coarse levels of the nested start, whose solution is a start, not a
// result (docs/SOLVER.md "Nested start"); on a job's own grid when its
// numerics.stall_window asks for it (docs/SOLVER.md "Stalled outer
// iterations"). Not part of a checkpoint: a resumed solve starts a new window.
//
// Stalled after iteration n when the residual max(R_c, R_m) of the last
// `window` iterations has not fallen below `factor` × the least residual of
// all iterations before them. A converging loop halves its residual in far
// fewer than 100 iterations (the slowest measured coarse level: 4 decades
// in 397 iterations, a halving every 30).
#pragma once

#include <deque>

namespace gridfree {

class StallMonitor {
 public:
  explicit StallMonitor(int window, double factor = 0.5) : window_(window), factor_(factor) {}

  // Feeds one iteration's residual; true once stalled.
  bool stalled(double residual);

 private:
  int window_;
  double factor_;
  std::deque<double> recent_;  // the last `window` residuals
  double best_before_ = -1;    // least residual before them (-1: none yet)
};

}  // namespace gridfree
