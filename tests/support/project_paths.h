// SPDX-License-Identifier: GPL-3.0-or-later
// Where the tests find the project: its source tree, the built gridfree
// executable and the fake worker (from GRIDFREE_SOURCE_DIR and
// GRIDFREE_BIN_DIR, which every test is compiled with).
#pragma once

#include <filesystem>

namespace gridfree::test_support {

inline const std::filesystem::path kSourceDir = GRIDFREE_SOURCE_DIR;
inline const std::filesystem::path kGridfreeExe = std::filesystem::path(GRIDFREE_BIN_DIR) / "gridfree";
// tests/fixtures/fake_worker.sh: a stand-in for gridfree-worker whose
// behaviour is chosen by the case name (see the script).
inline const std::filesystem::path kFakeWorker = kSourceDir / "tests/fixtures/fake_worker.sh";

}  // namespace gridfree::test_support
