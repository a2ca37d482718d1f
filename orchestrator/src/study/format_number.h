// SPDX-License-Identifier: GPL-3.0-or-later
// One number through a printf format ("%.3g", "%.0f", …), for the
// sentences the planner and the adaptive scheduler write.
#pragma once

#include <cstdio>
#include <string>

namespace gridfree {

inline std::string format_number(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace gridfree
