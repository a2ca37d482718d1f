// SPDX-License-Identifier: GPL-3.0-or-later
#include "exec/worker_path.h"

#include <cstdlib>

namespace gridfree {

std::filesystem::path own_executable_dir() {
  std::error_code ec;
  auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return std::filesystem::current_path();
  return exe.parent_path();
}

std::filesystem::path default_worker_path() {
  if (const char* env = std::getenv("GRIDFREE_WORKER"); env != nullptr && *env != '\0')
    return env;
  return own_executable_dir() / "gridfree-worker";
}

}  // namespace gridfree
