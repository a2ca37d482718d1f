// SPDX-License-Identifier: GPL-3.0-or-later
#include "output_path.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "core/input_error.h"

namespace gridfree::worker_cli {

void check_output_path(const std::string& option, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return;
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec))
    throw InputError(option, "'" + path + "' is an existing folder; give a file name inside it");
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::exists(folder, ec))
    throw InputError(option, "cannot write '" + path + "': the folder '" + folder.string() +
                                 "' does not exist (create it first)");
  if (!fs::is_directory(folder, ec))
    throw InputError(option, "cannot write '" + path + "': '" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(option, "cannot write '" + path + "': the folder '" + folder.string() + "' is not writable");
}

}  // namespace gridfree::worker_cli
