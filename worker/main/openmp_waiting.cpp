// SPDX-License-Identifier: GPL-3.0-or-later
#include "openmp_waiting.h"

#include <unistd.h>

#include <array>
#include <cstdlib>

namespace gridfree::worker_cli {

void use_default_openmp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  // The executable's real path (not /proc/self/exe itself, which would
  // rename the process "exe" in ps and pgrep).
  std::array<char, 4096> path{};
  const ssize_t len = ::readlink("/proc/self/exe", path.data(), path.size() - 1);
  if (len <= 0 || static_cast<std::size_t>(len) >= path.size() - 1) return;
  if (::setenv(kWaitVariable, kWaitDefault, 0) != 0) return;
  ::execv(path.data(), argv);
  // Only reached when the exec failed: run on with libgomp's default.
}

}  // namespace gridfree::worker_cli
