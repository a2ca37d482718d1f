// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree status` as it is now, not as last stored: a job shown running
// whose run was killed is "orphaned", a "running" study nobody works on is
// "queued", cancelled jobs have a column, and no ETA is shown for a study
// with work left that nobody works on.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/process_identity.h"
#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace status_cli {
namespace {

namespace fs = std::filesystem;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;

// gridfree ARGS in `dir`: exit code and stdout (stderr in dir/status_err.txt).
gridfree::test_support::CommandRun status_gridfree(const fs::path& dir, const std::string& args) {
  return gridfree::test_support::run_command(
      "cd " + shell_quote(dir.string()) + " && " + shell_quote(kGridfreeExe.string()) + " " + args,
      dir / "status_err.txt");
}

TEST(StatusCli, AKilledRunsJobIsOrphanedItsStudyQueuedCancelledCountedAndNoEta) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("status_cli", "orphaned");
  const auto study = gridfree::test_support::write_ok_study(dir, "s");
  ASSERT_EQ(status_gridfree(dir, "submit " + shell_quote(study.string()) + " --db g.sqlite").exit_code, 0);
  const auto db = dir / "g.sqlite";
  // What a run killed by SIGKILL leaves: the study and one job "running",
  // owned by a process of this host that no longer exists (pid 1 with
  // another start time); one job cancelled.
  const std::string gone = gridfree::host_name() + ":1:999999999999";
  sqlite_query(db, "UPDATE studies SET status = 'running'");
  sqlite_query(db, "UPDATE jobs SET status = 'running', owner = '" + gone + "', attempts = 1 WHERE id = "
                   "(SELECT MIN(id) FROM jobs)");
  sqlite_query(db, "UPDATE jobs SET status = 'cancelled' WHERE id = (SELECT MAX(id) FROM jobs)");
  ASSERT_EQ(sqlite_query(db, "SELECT status, COUNT(*) FROM jobs GROUP BY status ORDER BY status"),
            "cancelled|1\nqueued|1\nrunning|1");

  auto r = status_gridfree(dir, "status s --db g.sqlite --json");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out)[0];
  EXPECT_EQ(j["status"], "queued");
  EXPECT_EQ(j["stored_status"], "running");
  EXPECT_EQ(j["running"], 0);
  EXPECT_EQ(j["orphaned"], 1);
  EXPECT_EQ(j["cancelled"], 1);
  EXPECT_TRUE(j["detail"]["running"].empty()) << j["detail"].dump();
  EXPECT_TRUE(j["detail"]["eta"]["seconds"].is_null()) << j["detail"].dump();

  r = status_gridfree(dir, "status s --db g.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("cancelled"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("orphaned"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("running jobs"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\nETA "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("no ETA: no run or daemon works on this study now"), std::string::npos) << r.out;
  // The table row: s, queued, 3 jobs, 1 queued, 0 running, 1 orphaned, 0 done, 0 failed, 1 cancelled.
  EXPECT_NE(r.out.find("queued"), std::string::npos);
  const auto row = r.out.substr(r.out.find("\ns ") + 1, r.out.find('\n', r.out.find("\ns ") + 1) - r.out.find("\ns ") - 1);
  char name[64], status[32];
  int jobs = 0, queued = 0, running = 0, orphaned = 0, done = 0, failed = 0, cancelled = 0;
  ASSERT_EQ(std::sscanf(row.c_str(), "%63s %31s %d %d %d %d %d %d %d", name, status, &jobs, &queued, &running,
                        &orphaned, &done, &failed, &cancelled),
            9)
      << row;
  EXPECT_STREQ(status, "queued");
  EXPECT_EQ(jobs, 3);
  EXPECT_EQ(queued, 1);
  EXPECT_EQ(running, 0);
  EXPECT_EQ(orphaned, 1);
  EXPECT_EQ(cancelled, 1);
  // Read-only: nothing was requeued.
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE status = 'running'"), "1");
}

}  // namespace
}  // namespace status_cli
