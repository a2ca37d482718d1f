// SPDX-License-Identifier: GPL-3.0-or-later
// Whether Debian's OpenFOAM is installed (its solvers on PATH and
// /usr/share/openfoam, the WM_PROJECT_DIR they need): the OpenFOAM tests
// assert it, so a machine without it fails them instead of skipping
// (scripts/install-deps.sh test installs it).
#pragma once

#include <filesystem>

#include "run_command.h"

namespace gridfree::test_support {

inline bool openfoam_present() {
  return run_merged("command -v icoFoam && command -v blockMesh").code == 0 &&
         std::filesystem::is_directory("/usr/share/openfoam");
}

}  // namespace gridfree::test_support
