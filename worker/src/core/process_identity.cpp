// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/process_identity.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace gridfree {

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "localhost";
  return buf;
}

std::string process_start_time(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return "";
  // The command name (field 2) may hold spaces: fields are counted after its ')'.
  const auto close = line.rfind(')');
  if (close == std::string::npos || close + 2 > line.size()) return "";
  std::istringstream rest(line.substr(close + 2));
  std::string field;
  for (int i = 3; i <= 22 && (rest >> field); ++i)
    if (i == 22) return field;
  return "";
}

std::string process_identity_string(long pid) {
  return host_name() + ":" + std::to_string(pid) + ":" + process_start_time(pid);
}

}  // namespace gridfree
