// Process identity for job claims (see owner.h).
#include "store/owner.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <vector>

namespace gridfree {
namespace {

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "localhost";
  return buf;
}

// Field 22 of /proc/<pid>/stat (start time in clock ticks), "" if absent.
std::string start_time(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return "";
  const auto close = line.rfind(')');
  if (close == std::string::npos) return "";
  std::istringstream rest(line.substr(close + 2));
  std::string field;
  for (int i = 3; i <= 22 && (rest >> field); ++i) {
    if (i == 22) return field;
  }
  return "";
}

}  // namespace

std::string this_process_owner() {
  const long pid = static_cast<long>(getpid());
  return host_name() + ":" + std::to_string(pid) + ":" + start_time(pid);
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
  const std::string now = start_time(pid);
  return !now.empty() && now == owner.substr(b + 1);
}

}  // namespace gridfree
