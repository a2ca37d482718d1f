// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree` end to end with the fake worker (tests/fixtures/fake_worker.sh
// as GRIDFREE_WORKER): validate, the broken-study corpus (exit 2, every
// problem's JSON pointer, no database created or changed), run with mixed
// outcomes (exit 3, retries, reuse on rerun), kill -9 of a run then rerun
// (complete, no duplicate results, integrity ok), daemon stop/restart.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <optional>
#include <regex>
#include <vector>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::kFakeWorker;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::kSourceDir;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::spawn_gridfree_in;
using gridfree::test_support::sqlite_int;
using gridfree::test_support::sqlite_query;
using gridfree::test_support::wait_until;

fs::path temp_dir(const std::string& name) { return gridfree::test_support::fresh_scratch_dir("cli_test", name); }

using gridfree::test_support::shell_quote;

using Output = gridfree::test_support::MergedRun;

// Runs a shell command line in `dir` with the fake worker; stdout+stderr.
Output gridfree_merged(const fs::path& dir, const std::string& args, const std::string& env = "") {
  return gridfree::test_support::run_merged("cd " + shell_quote(dir.string()) + " && GRIDFREE_WORKER=" +
                                            shell_quote(kFakeWorker.string()) + " " + env + " " +
                                            shell_quote(kGridfreeExe.string()) + " " + args);
}

// A study with one series per case name (the fake worker's mode) on 4 grids.
fs::path write_cases_study(const fs::path& dir, const std::string& name, const std::vector<std::string>& cases) {
  auto doc = quickstart_document();
  doc["name"] = name;
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = nlohmann::json::object();
  for (const auto& c : cases) doc["cases"][c] = pc1;
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.5}}};
  const auto file = dir / (name + ".json");
  std::ofstream(file) << doc.dump(2);
  return file;
}

int results_count(const fs::path& db) { return sqlite_int(db, "SELECT COUNT(*) FROM results"); }

TEST(OrchestratorCli, ValidateAndPlanTheShippedStudies) {
  const auto dir = temp_dir("validate");
  auto out = gridfree_merged(dir, "validate " + shell_quote((kSourceDir / "studies/quickstart.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_NE(out.text.find("ok: 2 series, 10 jobs"), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("warning"), std::string::npos) << out.text;  // 5 grids, finest Δ* 0.667
  out = gridfree_merged(dir, "validate " + shell_quote((kSourceDir / "studies/bursting_bubble_paper.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_NE(out.text.find("ok: 12 series, 216 jobs"), std::string::npos) << out.text;
  out = gridfree_merged(dir, "plan --json " + shell_quote((kSourceDir / "studies/quickstart.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_EQ(nlohmann::json::parse(out.text)["jobs"], 10);
  EXPECT_FALSE(fs::exists(dir / "gridfree.sqlite"));
}

// validate and plan warn (exit 0) about grids that cannot give a converged
// verdict: 4 grids (1 degree of freedom), all coarser than Δ* = 2.
TEST(OrchestratorCli, ValidateAndPlanWarnAboutCoarseOrFewGrids) {
  const auto dir = temp_dir("warn");
  auto doc = quickstart_document();
  doc["grids"] = {{"delta_star", {4.0, 3.3, 2.8, 2.5}}};
  const auto file = dir / "coarse.json";
  std::ofstream(file) << doc.dump(2);
  for (const char* cmd : {"validate ", "plan "}) {
    const auto out = gridfree_merged(dir, cmd + shell_quote(file.string()));
    EXPECT_EQ(out.code, 0) << out.text;
    EXPECT_NE(out.text.find("warning: 4 grid(s) leave 1 degree(s) of freedom"), std::string::npos) << out.text;
    EXPECT_NE(out.text.find("warning: every grid is coarser than Δ* = 2"), std::string::npos) << out.text;
  }
}

TEST(OrchestratorCli, BrokenStudiesExitTwoNameThePointerAndLeaveNoDatabase) {
  const auto corpus = kSourceDir / "tests/fixtures/broken_studies";
  std::ifstream in(corpus / "expected_pointers.json");
  const auto expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 15u);
  const auto dir = temp_dir("broken");
  // An existing database must not change either.
  const auto good = write_cases_study(dir, "good", {"ok"});
  ASSERT_EQ(gridfree_merged(dir, "submit " + shell_quote(good.string()) + " --db existing.sqlite").code, 0);
  const std::string before = sqlite_query(dir / "existing.sqlite", "SELECT COUNT(*), MAX(id) FROM studies") +
                             sqlite_query(dir / "existing.sqlite", "SELECT COUNT(*) FROM jobs");
  for (const auto& [file, pointer] : expected.items()) {
    const std::string study = shell_quote((corpus / file).string());
    for (const std::string cmd : {"validate ", "run ", "submit "}) {
      const std::string db = cmd == "validate " ? "" : " --db new.sqlite";
      const auto out = gridfree_merged(dir, cmd + study + db);
      EXPECT_EQ(out.code, 2) << cmd << file << "\n" << out.text;
      EXPECT_NE(out.text.find(pointer.get<std::string>()), std::string::npos)
          << cmd << file << " should name " << pointer << ":\n" << out.text;
    }
    EXPECT_EQ(gridfree_merged(dir, "run " + study + " --db existing.sqlite").code, 2) << file;
    EXPECT_FALSE(fs::exists(dir / "new.sqlite")) << file;
    EXPECT_FALSE(fs::exists(dir / "gridfree.sqlite")) << file;
  }
  EXPECT_EQ(sqlite_query(dir / "existing.sqlite", "SELECT COUNT(*), MAX(id) FROM studies") +
                sqlite_query(dir / "existing.sqlite", "SELECT COUNT(*) FROM jobs"),
            before);
}

TEST(OrchestratorCli, RunRecordsEveryOutcomeRetriesOnceAndReusesOnRerun) {
  const auto dir = temp_dir("run");
  const auto study = write_cases_study(dir, "mixed", {"ok", "noconv", "flaky", "crash"});
  const std::string log = (dir / "solves.log").string();
  auto out = gridfree_merged(dir, "run " + shell_quote(study.string()) + " -j 2 --db g.sqlite",
                             "GRIDFREE_FAKE_LOG=" + shell_quote(log));
  EXPECT_EQ(out.code, 3) << out.text;  // some jobs did not converge
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM results"), "16");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM results WHERE status = 'converged'"), "8");  // ok + flaky
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM results WHERE status = 'not_converged'"), "4");
  EXPECT_EQ(
      sqlite_query(db, "SELECT MAX(attempts) FROM jobs j JOIN results r ON r.job_id = j.id WHERE r.status = 'failed'"),
      "2");
  EXPECT_EQ(sqlite_query(db, "SELECT status FROM studies"), "failed");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM series WHERE status = 'done'"), "4");
  // ok's dp* is 1159 + Δ* exactly (fake worker): the extrapolated f0 is 1159.
  const auto f0 = sqlite_query(db, "SELECT e.f0 FROM extrapolations e JOIN series s ON s.id = e.series_id "
                          "WHERE s.case_name = 'ok' AND e.chosen = 1");
  ASSERT_FALSE(f0.empty()) << sqlite_query(db, "SELECT * FROM extrapolations");
  EXPECT_NEAR(std::stod(f0), 1159.0, 1e-6);
  // 16 jobs + one retry each for flaky (4) and crash (4).
  auto lines = [&] {
    std::ifstream f(log);
    int n = 0;
    for (std::string l; std::getline(f, l);) ++n;
    return n;
  };
  EXPECT_EQ(lines(), 24);
  EXPECT_TRUE(fs::exists(dir / "reports/mixed"));
  out = gridfree_merged(dir, "run " + shell_quote(study.string()) + " -j 2 --db g.sqlite",
                        "GRIDFREE_FAKE_LOG=" + shell_quote(log));
  EXPECT_EQ(out.code, 3) << out.text;
  EXPECT_EQ(lines(), 24);  // nothing ran again
  out = gridfree_merged(dir, "status mixed --db g.sqlite --json");
  EXPECT_EQ(out.code, 0) << out.text;
  const auto st = nlohmann::json::parse(out.text);
  EXPECT_EQ(st[0]["converged"], 8);
  EXPECT_EQ(st[0]["failed"], 8);
  // status's U₀ is the report's (series.csv), as the extrapolation gave it,
  // not 1.25|f0 − f₁| + σ_RE recomputed without the averaged method's widening.
  std::optional<double> status_u0;
  for (const auto& row : st[0]["detail"]["series"])
    if (row["series"].get<std::string>().rfind("ok ", 0) == 0 && row["u0"].is_number()) status_u0 = row["u0"].get<double>();
  ASSERT_TRUE(status_u0) << st.dump();
  // series.csv: unquoted fields up to u0 (series, f0, verdict, attention,
  // concerns, factor columns: no commas in this study's values before it).
  const auto fields = [](const std::string& text) {
    std::vector<std::string> parts(1);
    for (char ch : text) {
      if (ch == ',')
        parts.emplace_back();
      else
        parts.back().push_back(ch);
    }
    return parts;
  };
  std::ifstream csv(dir / "reports/mixed/series.csv");
  std::string line;
  std::getline(csv, line);
  const auto header = fields(line);
  const auto u0_column = std::find(header.begin(), header.end(), "u0") - header.begin();
  ASSERT_LT(static_cast<std::size_t>(u0_column), header.size()) << line;
  std::optional<double> report_u0;
  while (std::getline(csv, line))
    if (line.rfind("ok ", 0) == 0) report_u0 = std::stod(fields(line).at(static_cast<std::size_t>(u0_column)));
  ASSERT_TRUE(report_u0);
  EXPECT_NEAR(*status_u0, *report_u0, 1e-9 * std::fabs(*report_u0));
  EXPECT_EQ(sqlite_query(db, "PRAGMA integrity_check"), "ok");
}

TEST(OrchestratorCli, KillMinusNineThenRerunCompletesWithoutDuplicates) {
  const auto dir = temp_dir("kill9");
  const auto study = write_cases_study(dir, "killme", {"ok", "ok2"});
  const auto db = dir / "g.sqlite";
  const pid_t pid = spawn_gridfree_in(dir, "run " + shell_quote(study.string()) + " -j 2 --db g.sqlite", "0.4");
  ASSERT_TRUE(wait_until([&] { return results_count(db) >= 2; }, 60));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_LT(results_count(db), 8);
  const auto out =
      gridfree_merged(dir, "run " + shell_quote(study.string()) + " -j 2 --db g.sqlite", "GRIDFREE_FAKE_SLEEP=0.05");
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "8|8");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE status <> 'done'"), "0");
  EXPECT_EQ(sqlite_query(db, "SELECT status FROM studies"), "done");
  EXPECT_EQ(sqlite_query(db, "PRAGMA integrity_check"), "ok");
}

TEST(OrchestratorCli, DaemonStopsOnSigtermAndARestartFinishesTheQueue) {
  const auto dir = temp_dir("daemon");
  const auto study = write_cases_study(dir, "queued", {"ok", "ok2", "ok3"});
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(gridfree_merged(dir, "submit " + shell_quote(study.string()) + " --db g.sqlite").code, 0);
  pid_t pid = spawn_gridfree_in(dir, "daemon -j 2 --db g.sqlite", "0.4");
  ASSERT_TRUE(wait_until([&] { return results_count(db) >= 2; }, 60));
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_TRUE(wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 10));
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE status = 'running'"), "0");  // released
  EXPECT_LT(results_count(db), 12);
  // Every log line starts with its time; a requeue is named with its count.
  const std::regex stamped(R"(^\[\d{4}-\d\d-\d\d \d\d:\d\d:\d\d\] )");
  auto check_log = [&](bool may_requeue) {
    std::ifstream log(dir / "spawned.log");
    int lines = 0;
    for (std::string line; std::getline(log, line); ++lines) {
      EXPECT_TRUE(std::regex_search(line, stamped)) << line;
      if (line.find("requeued") != std::string::npos) {
        EXPECT_TRUE(may_requeue) << line;
        EXPECT_TRUE(std::regex_search(line, std::regex(R"(, [1-9]\d* in-flight job\(s\) requeued)"))) << line;
      }
    }
    EXPECT_GT(lines, 0);
  };
  check_log(true);
  pid = spawn_gridfree_in(dir, "daemon -j 2 --db g.sqlite", "0.05");
  ASSERT_TRUE(wait_until([&] { return sqlite_query(db, "SELECT status FROM studies") == "done"; }, 60));
  kill(pid, SIGINT);
  ASSERT_TRUE(wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 10));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "12|12");
  EXPECT_EQ(sqlite_query(db, "PRAGMA integrity_check"), "ok");
  check_log(false);  // idle when stopped: nothing requeued, nothing said about it
}

TEST(OrchestratorCli, DaemonRefusesAMissingDatabase) {
  const auto dir = temp_dir("daemon_typo");
  const auto out = gridfree_merged(dir, "daemon --db typo.sqlite");
  EXPECT_EQ(out.code, 2) << out.text;
  EXPECT_NE(out.text.find("typo.sqlite"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("submit or run a study first"), std::string::npos) << out.text;
  EXPECT_FALSE(fs::exists(dir / "typo.sqlite"));
}

}  // namespace
