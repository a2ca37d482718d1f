// SPDX-License-Identifier: GPL-3.0-or-later
// Two processes on one database at once: two `run`s of the same study, and
// a `run` beside a `daemon`. Jobs are claimed atomically (BEGIN IMMEDIATE,
// store/store_jobs.cpp), so each job is solved once; both processes finish
// cleanly (exit 0) with every job's result stored once, and the daemon keeps
// serving after the run's study is done.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

// Four series (2 convection × 2 drag) on five grids: 20 jobs, enough for two
// processes to interleave their claims.
fs::path write_twin_study(const fs::path& dir) {
  auto doc = ts::quickstart_document();
  doc["name"] = "twin";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"ok", pc1}};
  doc["factors"] = {{"convection", {"superbee", "fou"}}, {"fwhm_dp", {6}}, {"drag", {"bvk", "wen_yu"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.8, 2.4}}};
  const auto file = dir / "twin.json";
  std::ofstream(file) << doc.dump(2);
  return file;
}

TEST(ConcurrentRuns, TwoRunsOfOneStudyBothFinishAndSolveEachJobOnce) {
  const auto dir = ts::fresh_scratch_dir("concurrent_runs", "two_runs");
  const auto study = write_twin_study(dir);
  const auto db = dir / "g.sqlite";
  const std::string args = "run " + ts::shell_quote(study.string()) + " -j 2 --db g.sqlite";
  // Both start on a database that does not exist yet: creation and the
  // study's submission race as well.
  const pid_t a = ts::spawn_gridfree_in(dir, args, "0.1", "a.log");
  const pid_t b = ts::spawn_gridfree_in(dir, args, "0.1", "b.log");
  const int code_a = ts::exit_code_within(a, 120);
  const int code_b = ts::exit_code_within(b, 120);
  EXPECT_EQ(code_a, 0) << ts::slurp(dir / "a.log");
  EXPECT_EQ(code_b, 0) << ts::slurp(dir / "b.log");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "20|20");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM jobs"), "20");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT SUM(attempts) FROM jobs"), "20");  // none solved twice
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM studies"), "1");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT status FROM studies"), "done");
  EXPECT_EQ(ts::sqlite_query(db, "PRAGMA integrity_check"), "ok");
  for (const auto* log : {"a.log", "b.log"}) EXPECT_EQ(ts::slurp(dir / log).find("internal"), std::string::npos);
}

TEST(ConcurrentRuns, ARunBesideADaemonFinishesAndTheDaemonKeepsServing) {
  const auto dir = ts::fresh_scratch_dir("concurrent_runs", "run_daemon");
  const auto study = write_twin_study(dir);
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(ts::gridfree_in(dir, "submit " + ts::shell_quote(study.string()) + " --db g.sqlite").exit_code, 0);
  const pid_t daemon = ts::spawn_gridfree_in(dir, "daemon -j 2 --db g.sqlite", "0.1", "daemon.log");
  const pid_t run = ts::spawn_gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 2 --db g.sqlite",
                                          "0.1", "run.log");
  EXPECT_EQ(ts::exit_code_within(run, 120), 0) << ts::slurp(dir / "run.log");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "20|20");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT SUM(attempts) FROM jobs"), "20");
  // The daemon is still serving: a study submitted now is worked by it.
  auto second = ts::quickstart_document();
  second["name"] = "after";
  second["cases"] = {{"ok", second["cases"]["PC1"]}};
  second["factors"] = {{"convection", {"minmod"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  second["design"] = "factorial";
  second["grids"] = {{"delta_star", {5.0, 4.0, 3.3}}};
  std::ofstream(dir / "after.json") << second.dump(2);
  ASSERT_EQ(ts::gridfree_in(dir, "submit after.json --db g.sqlite").exit_code, 0);
  EXPECT_TRUE(ts::wait_until(
      [&] { return ts::sqlite_query(db, "SELECT status FROM studies WHERE name = 'after'") == "done"; }, 60))
      << ts::slurp(dir / "daemon.log");
  kill(daemon, SIGTERM);
  EXPECT_EQ(ts::exit_code_within(daemon, 30), 0) << ts::slurp(dir / "daemon.log");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "23|23");
  EXPECT_EQ(ts::sqlite_query(db, "PRAGMA integrity_check"), "ok");
}

}  // namespace
