// SPDX-License-Identifier: GPL-3.0-or-later
// Polling for a condition that another process makes true.
#pragma once

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

}  // namespace gridfree::test_support
