// SPDX-License-Identifier: GPL-3.0-or-later
// Stall test of the outer iterations (stall_monitor.h).
#include "flow/stall_monitor.h"

#include <algorithm>

namespace gridfree {

bool StallMonitor::stalled(double residual) {
  recent_.push_back(residual);
  if (static_cast<int>(recent_.size()) <= window_) return false;
  const double leaving = recent_.front();
  recent_.pop_front();
  best_before_ = best_before_ < 0 ? leaving : std::min(best_before_, leaving);
  const double best_recent = *std::min_element(recent_.begin(), recent_.end());
  return best_recent > factor_ * best_before_;
}

}  // namespace gridfree
