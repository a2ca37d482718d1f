// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree` study life cycle with the fake worker (tests/fixtures/
// fake_worker.sh): a changed study under a stored name is refused with the
// way out (--replace), `run --replace` reuses finished identical jobs and
// keeps the ones no study needs any more,
// `delete` removes a study and the jobs only it used (database and run
// folders) but keeps shared ones, a study's own timeout_s kills a hanging
// job, and `plan` lists every grid and warns about close neighbours.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::sqlite_query;

// One case (`mode` picks the fake worker's behaviour) on the given grids.
fs::path write_one_series_study(const fs::path& dir, const std::string& file, const std::string& name,
                                const std::string& mode, const std::vector<double>& grids,
                                const nlohmann::json& extra = nlohmann::json::object()) {
  auto doc = quickstart_document();
  doc["name"] = name;
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{mode, pc1}};
  doc.erase("factors");  // the defaults: one series
  doc.erase("design");
  doc["grids"] = {{"delta_star", grids}};
  doc.merge_patch(extra);
  const auto path = dir / file;
  std::ofstream(path) << doc.dump(2);
  return path;
}

TEST(StudyLifecycle, ChangedStudyNeedsReplaceAndReusesFinishedJobs) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "replace");
  write_one_series_study(dir, "s1.json", "s", "ok", {5.0, 4.0, 3.3, 2.5});
  ASSERT_EQ(gridfree_in(dir, "run s1.json -j 2 --db g.sqlite").exit_code, 0);
  write_one_series_study(dir, "s2.json", "s", "ok", {5.0, 4.0, 3.3, 2.0});  // one grid changed

  const CommandRun refused = gridfree_in(dir, "run s2.json -j 2 --db g.sqlite");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--replace"), std::string::npos) << refused.err;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs"), "4");  // untouched

  const CommandRun replaced = gridfree_in(dir, "run s2.json -j 2 --db g.sqlite --replace");
  EXPECT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_NE(replaced.err.find("1 new, 3 already done"), std::string::npos) << replaced.err;
  // The Δ* 2.5 job stays, needed by no study, until gc (its result and folder too).
  EXPECT_NE(replaced.err.find("1 job(s) no study needs any more kept"), std::string::npos) << replaced.err;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs"), "5");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs WHERE id NOT IN (SELECT job_id FROM study_jobs) "
                                           "AND status = 'done'"),
            "1");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM studies"), "1");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT MIN(delta_star_nominal) FROM v_results"), "2.0");
  EXPECT_EQ(
      sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM v_series WHERE f0 IS NOT NULL AND finest_u IS NOT NULL"),
      "1");
}

TEST(StudyLifecycle, DeleteKeepsJobsOtherStudiesUse) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "delete");
  write_one_series_study(dir, "a.json", "a", "ok", {5.0, 4.0, 3.3, 2.5});
  write_one_series_study(dir, "b.json", "b", "ok", {5.0, 4.0, 3.3, 2.0});  // shares three grids with a
  ASSERT_EQ(gridfree_in(dir, "run a.json -j 2 --db g.sqlite").exit_code, 0);
  ASSERT_EQ(gridfree_in(dir, "run b.json -j 2 --db g.sqlite").exit_code, 0);
  ASSERT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs"), "5");
  const std::string only_a =
      sqlite_query(dir / "g.sqlite", "SELECT job_hash FROM v_results WHERE study = 'a' AND delta_star_nominal = 2.5");
  ASSERT_TRUE(fs::is_directory(dir / "g.sqlite.runs" / only_a.substr(0, 2) / only_a));

  const CommandRun del = gridfree_in(dir, "delete a --db g.sqlite");
  EXPECT_EQ(del.exit_code, 0) << del.err;
  EXPECT_NE(del.out.find("1 job(s)"), std::string::npos) << del.out;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs"), "4");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM results"), "4");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT name FROM studies"), "b");
  EXPECT_FALSE(fs::exists(dir / "g.sqlite.runs" / only_a.substr(0, 2) / only_a));
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "PRAGMA foreign_key_check"), "");

  EXPECT_EQ(gridfree_in(dir, "delete a --db g.sqlite").exit_code, 2);  // gone
}

TEST(StudyLifecycle, CancelAndResubmitSayWhatTheyDo) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "cancel");
  write_one_series_study(dir, "done.json", "finished", "ok", {5.0, 4.0, 3.3, 2.5});
  ASSERT_EQ(gridfree_in(dir, "run done.json -j 2 --db g.sqlite").exit_code, 0);
  const CommandRun late = gridfree_in(dir, "cancel finished --db g.sqlite");
  EXPECT_EQ(late.exit_code, 0) << late.err;
  EXPECT_NE(late.out.find("study finished is already finished (done); nothing changed"), std::string::npos)
      << late.out;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT status FROM studies WHERE name = 'finished'"), "done");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM events WHERE kind = 'cancel'"), "0");

  write_one_series_study(dir, "q.json", "queued", "ok", {4.8, 4.2, 3.0, 2.2});  // none shared
  ASSERT_EQ(gridfree_in(dir, "submit q.json --db g.sqlite").exit_code, 0);
  const CommandRun cancel = gridfree_in(dir, "cancel queued --db g.sqlite");
  EXPECT_EQ(cancel.exit_code, 0) << cancel.err;
  EXPECT_NE(cancel.out.find("cancelled queued: 4 queued job(s) cancelled"), std::string::npos) << cancel.out;
  const CommandRun again = gridfree_in(dir, "cancel queued --db g.sqlite");
  EXPECT_NE(again.out.find("already cancelled; nothing changed"), std::string::npos) << again.out;
  const CommandRun resubmit = gridfree_in(dir, "submit q.json --db g.sqlite");
  EXPECT_EQ(resubmit.exit_code, 0) << resubmit.err;
  EXPECT_NE(resubmit.out.find("requeued cancelled study queued: 4 cancelled job(s) queued again"), std::string::npos)
      << resubmit.out;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT status FROM studies WHERE name = 'queued'"), "queued");
  const CommandRun same = gridfree_in(dir, "submit q.json --db g.sqlite");
  EXPECT_NE(same.out.find("already submitted (nothing changed) queued"), std::string::npos) << same.out;
}

// Off a terminal: one line per finished job with " | " between the counts
// (and their ETA) and the job, failures at warn, converged jobs at info; the
// report is written once at the end of a run, not twice.
TEST(StudyLifecycle, RunLogLinesSeparateTheJobAndTheReportIsWrittenOnce) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "loglines");
  write_one_series_study(dir, "n.json", "n", "noconv", {5.0, 4.0});
  const CommandRun r = gridfree_in(dir, "run n.json -j 1 --db g.sqlite");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  std::size_t failed_lines = 0, reports = 0;
  std::istringstream err(r.err);
  for (std::string line; std::getline(err, line);) {
    if (line.find("charts written to") != std::string::npos) ++reports;
    if (line.find("] running ") == std::string::npos) continue;
    EXPECT_NE(line.find(" | noconv "), std::string::npos) << line;
    EXPECT_NE(line.find("[warning]"), std::string::npos) << line;
    ++failed_lines;
  }
  EXPECT_EQ(failed_lines, 2u) << r.err;
  EXPECT_EQ(reports, 1u) << r.err;
  write_one_series_study(dir, "o.json", "o", "ok", {5.0});
  const CommandRun ok = gridfree_in(dir, "run o.json -j 1 --db g.sqlite");
  EXPECT_NE(ok.err.find("[info] [1/1] running 0, failed 0, ETA "), std::string::npos) << ok.err;
  EXPECT_NE(ok.err.find(" | ok "), std::string::npos) << ok.err;
}

// `cancel` while `run` works the study: the running job finishes and run
// exits 130 (interrupted; the exit-code table), saying so — not 3, which
// means jobs failed.
TEST(StudyLifecycle, ACancelledRunExitsAsInterrupted) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "cancelrun");
  write_one_series_study(dir, "c.json", "c", "ok", {5.0, 4.0, 3.3, 2.5});
  const pid_t pid = gridfree::test_support::spawn_gridfree_in(dir, "run c.json -j 1 --db g.sqlite", "1");
  ASSERT_TRUE(gridfree::test_support::wait_until(
      [&] { return gridfree::test_support::sqlite_int(dir / "g.sqlite", "SELECT COUNT(*) FROM jobs WHERE status = 'running'") >= 1; },
      60));
  EXPECT_EQ(gridfree_in(dir, "cancel c --db g.sqlite").exit_code, 0);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream log(dir / "spawned.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("(cancelled; run again to resume)"), std::string::npos) << text;
}

TEST(StudyLifecycle, StudyTimeoutKillsAHangingJob) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "timeout");
  write_one_series_study(dir, "t.json", "t", "hang", {5.0}, {{"timeout_s", 0.5}});
  const CommandRun r = gridfree_in(dir, "run t.json -j 1 --db g.sqlite");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT status FROM jobs"), "failed");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT attempts FROM jobs"), "2");  // killed, retried once, killed again
  // The stability map's word for it (store/stability_view.h, report/stability_map.h).
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT outcome FROM v_stability"), "timed_out")
      << sqlite_query(dir / "g.sqlite", "SELECT reason FROM v_stability");
}

TEST(StudyLifecycle, PlanListsGridsAndWarnsAboutCloseNeighbours) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("lifecycle_cli_test", "plan");
  write_one_series_study(dir, "p.json", "p", "ok", {2.0, 1.9, 1.5});
  const CommandRun r = gridfree_in(dir, "plan p.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("16 x 105 x 5"), std::string::npos) << r.out;  // Δ* 1.9 → round(L*/1.9)
  EXPECT_NE(r.err.find("warning: case ok: /grids/delta_star/1"), std::string::npos) << r.err;
  const CommandRun j = gridfree_in(dir, "plan p.json --json");
  const auto plan = nlohmann::json::parse(j.out);
  ASSERT_EQ(plan["grids"].size(), 3u);
  EXPECT_EQ(plan["grids"][1]["delta_star_requested"], 1.9);
  EXPECT_NEAR(plan["grids"][1]["delta_star"].get<double>(), 1.926, 1e-3);
  // every warning printed on stderr is also in --json's "warnings", no more
  std::vector<std::string> printed;
  std::istringstream err(j.err);
  for (std::string line; std::getline(err, line);)
    if (line.rfind("warning: ", 0) == 0) printed.push_back(line.substr(9));
  EXPECT_GE(printed.size(), 2u) << j.err;  // the close neighbours and the grid design (3 grids, no freedom)
  EXPECT_EQ(plan["warnings"].get<std::vector<std::string>>(), printed) << j.err;
}

}  // namespace
