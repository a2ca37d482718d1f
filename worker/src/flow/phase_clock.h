// SPDX-License-Identifier: GPL-3.0-or-later
// Wall time per step of an outer iteration: each charge adds the seconds
// since the last charge (or construction) to one step's total.
#pragma once

#include <chrono>

namespace gridfree {

class PhaseClock {
 public:
  void charge(double& total) {
    const auto now = std::chrono::steady_clock::now();
    total += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace gridfree
