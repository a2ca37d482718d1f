// SPDX-License-Identifier: GPL-3.0-or-later
// Globs in the case folder: * inside a component, ** across folders, and
// the newest of several matches.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "external/case_glob.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

TEST(ExternalCaseGlob, Matching) {
  EXPECT_TRUE(case_glob_match("postProcessing/*/0/volFieldValue.dat", "postProcessing/meanU2/0/volFieldValue.dat"));
  EXPECT_FALSE(case_glob_match("postProcessing/*/0/volFieldValue.dat", "postProcessing/a/b/0/volFieldValue.dat"));
  EXPECT_TRUE(case_glob_match("postProcessing/**/volFieldValue.dat", "postProcessing/a/b/0/volFieldValue.dat"));
  EXPECT_TRUE(case_glob_match("**/log.*", "log.icoFoam"));  // ** also matches no folder
  EXPECT_TRUE(case_glob_match("./log.icoFoam", "log.icoFoam"));
  EXPECT_FALSE(case_glob_match("log.*", "sub/log.icoFoam"));
  EXPECT_FALSE(case_glob_match("*", ".gridfree_exit"));  // hidden files need an explicit dot
}

TEST(ExternalCaseGlob, NewestMatch) {
  namespace fs = std::filesystem;
  const auto dir = test_support::fresh_scratch_dir("external_glob", "newest");
  fs::create_directories(dir / "post" / "0");
  fs::create_directories(dir / "post" / "0.5");
  std::ofstream(dir / "post" / "0" / "v.dat") << "old\n";
  std::ofstream(dir / "post" / "0.5" / "v.dat") << "new\n";
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(dir / "post" / "0" / "v.dat", now - std::chrono::hours(1));
  fs::last_write_time(dir / "post" / "0.5" / "v.dat", now);
  EXPECT_EQ(newest_case_match(dir, "post/*/v.dat"), dir / "post" / "0.5" / "v.dat");
  fs::last_write_time(dir / "post" / "0" / "v.dat", now + std::chrono::hours(1));
  EXPECT_EQ(newest_case_match(dir, "post/*/v.dat"), dir / "post" / "0" / "v.dat");
  EXPECT_EQ(newest_case_match(dir, "post/0/v.dat"), dir / "post" / "0" / "v.dat");  // no wildcard
  EXPECT_FALSE(newest_case_match(dir, "post/*/w.dat"));
  EXPECT_FALSE(newest_case_match(dir, "nothing/*/v.dat"));
}

}  // namespace
}  // namespace gridfree
