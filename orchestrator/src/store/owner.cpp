// SPDX-License-Identifier: GPL-3.0-or-later
// Process identity for job claims (see owner.h).
#include "store/owner.h"

#include <unistd.h>

#include <string>

#include "core/process_identity.h"

namespace gridfree {

std::string this_process_owner() {
  const long pid = static_cast<long>(getpid());
  return process_identity_string(pid);
}

bool owner_alive(const std::string& owner, bool assume_other_hosts_dead) {
  const auto a = owner.find(':');
  const auto b = owner.find(':', a == std::string::npos ? a : a + 1);
  if (a == std::string::npos || b == std::string::npos) return !assume_other_hosts_dead;
  if (owner.substr(0, a) != host_name()) return !assume_other_hosts_dead;
  long pid = 0;
  try {
    pid = std::stol(owner.substr(a + 1, b - a - 1));
  } catch (...) {
    return false;
  }
  const std::string now = process_start_time(pid);
  return !now.empty() && now == owner.substr(b + 1);
}

}  // namespace gridfree
