// SPDX-License-Identifier: GPL-3.0-or-later
// Where the worker executable is: beside the orchestrator's own executable.
#pragma once

#include <filesystem>

namespace gridfree {

// Directory of the running executable (from /proc/self/exe).
std::filesystem::path own_executable_dir();

// `gridfree-worker` beside the running executable; GRIDFREE_WORKER overrides.
std::filesystem::path default_worker_path();

}  // namespace gridfree
