// SPDX-License-Identifier: GPL-3.0-or-later
// Checks an output file path before any work is done, so a typo in -o costs
// an exit 2 naming the path and the reason instead of a finished solve lost
// at the end (docs/INTERFACE.md §2).
#pragma once

#include <string>

namespace gridfree::worker_cli {

// Throws InputError(option, reason) if `path` names an existing folder, or
// its folder is missing, not a folder or not writable. "" (stdout) passes.
void check_output_path(const std::string& option, const std::string& path);

}  // namespace gridfree::worker_cli
