// SPDX-License-Identifier: GPL-3.0-or-later
// Run folders of jobs (exec/run_folders.h): the size of a job's folder in
// either layout, and its removal taking the shard folder with it only when
// the shard is left empty.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "exec/executor.h"
#include "exec/run_folders.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

void write_bytes_to(const fs::path& file, std::size_t n) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << std::string(n, 'x');
}

TEST(RunFolders, SizeInEitherLayoutAndRemovalWithItsEmptiedShard) {
  const auto root = test_support::fresh_scratch_dir("run_folders_test", "runs");
  const std::string a = "ab12", b = "ab34", flat = "cd56";
  write_bytes_to(run_dir_for(root, a) / "job.json", 100);
  write_bytes_to(run_dir_for(root, a) / "case" / "log.solver", 1000);
  write_bytes_to(run_dir_for(root, b) / "job.json", 7);
  write_bytes_to(root / flat / "job.json", 50);  // the flat layout of older versions
  EXPECT_EQ(run_folder_bytes(root, a), 1100u);
  EXPECT_EQ(run_folder_bytes(root, flat), 50u);
  EXPECT_EQ(run_folder_bytes(root, "ef78"), 0u);

  remove_run_folder(root, a);  // b still uses the shard "ab"
  EXPECT_FALSE(fs::exists(root / "ab" / a));
  EXPECT_TRUE(fs::exists(root / "ab" / b));
  remove_run_folder(root, b);  // now empty: gone
  EXPECT_FALSE(fs::exists(root / "ab"));
  remove_run_folder(root, flat);
  EXPECT_FALSE(fs::exists(root / flat));
  EXPECT_TRUE(fs::exists(root)) << "the runs root itself stays";
  // A name that is a shard's or a path is never removed.
  write_bytes_to(run_dir_for(root, "12ff") / "job.json", 1);
  remove_run_folders(root, {"12", "../x", ""});
  EXPECT_TRUE(fs::exists(root / "12" / "12ff" / "job.json"));
}

}  // namespace
}  // namespace gridfree
