// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run` when the report cannot be written (its folder cannot be
// created: a file is in the way): exit 1, no report path printed, the
// results still in the database; and a temporary report file left by a
// killed writer is removed by the next run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::shell_quote;
using gridfree::test_support::write_ok_study;

TEST(ReportFailure, RunExitsNonZeroAndNamesNoMissingFile) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("report_failure", "blocked");
  std::ofstream(dir / "blocker") << "a file where the report folder should go\n";
  const auto r = gridfree_in(dir, "run " + shell_quote(write_ok_study(dir, "reportless").string()) +
                                      " --db g.sqlite --out " + shell_quote((dir / "blocker" / "report").string()));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.find("report.html"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("report: not written"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "g.sqlite"));
}

TEST(ReportFailure, TempFilesOfAKilledWriterAreRemoved) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("report_failure", "stale");
  const auto out = dir / "out";
  fs::create_directories(out);
  // pid 2^22 + 1 is above Linux's largest pid (4194304): no such process.
  const auto stale = out / ".report.html.tmp-4194305-1";
  std::ofstream(stale) << "half a report";
  const auto r = gridfree_in(dir, "run " + shell_quote(write_ok_study(dir, "reportless").string()) +
                                      " --db g.sqlite --out " + shell_quote(out.string()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_FALSE(fs::exists(stale));
}

}  // namespace
