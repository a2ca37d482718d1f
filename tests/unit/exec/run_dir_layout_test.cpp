// SPDX-License-Identifier: GPL-3.0-or-later
// Run folders sharded by the first two hex digits of the job hash
// (exec/executor.h run_dir_for), with folders of the older flat layout
// still found where they are.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "exec/executor.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

const std::string kHash = "ab34cdef0123456789abcdef0123456789abcdef0123456789abcdef01234567";

TEST(RunDirLayout, ShardsByTheFirstTwoHexDigits) {
  const fs::path root = test_support::fresh_scratch_dir("exec_unit", "sharded");
  EXPECT_EQ(run_dir_for(root, kHash), root / "ab" / kHash);
  const fs::path dir = prepare_run_dir(root, kHash, "{}");
  EXPECT_EQ(dir, root / "ab" / kHash);
  EXPECT_TRUE(fs::is_regular_file(root / "ab" / kHash / "job.json"));
  EXPECT_FALSE(fs::exists(root / kHash));
}

TEST(RunDirLayout, KeepsAFolderOfTheFlatLayout) {
  const fs::path root = test_support::fresh_scratch_dir("exec_unit", "flat");
  fs::create_directories(root / kHash);  // left by an older version (its checkpoint, say)
  EXPECT_EQ(run_dir_for(root, kHash), root / kHash);
  EXPECT_EQ(prepare_run_dir(root, kHash, "{}"), root / kHash);
  EXPECT_FALSE(fs::exists(root / "ab"));
}

TEST(RunDirLayout, LeavesNamesThatAreNotPlainHashesFlat) {
  const fs::path root = "/nonexistent-root";
  EXPECT_EQ(run_dir_for(root, ""), root / "");
  EXPECT_EQ(run_dir_for(root, "ab"), root / "ab");
  EXPECT_EQ(run_dir_for(root, "../x"), root / "../x");
}

}  // namespace
}  // namespace gridfree
