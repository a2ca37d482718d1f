// `gridfree` end to end with the fake worker (tests/fixtures/fake_worker.sh
// as GRIDFREE_WORKER): validate, the broken-study corpus (exit 2, every
// problem's JSON pointer, no database created or changed), run with mixed
// outcomes (exit 3, retries, reuse on rerun), kill -9 of a run then rerun
// (complete, no duplicate results, integrity ok), daemon stop/restart.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "run_command.h"
#include "scratch_dir.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
const fs::path kSource = GRIDFREE_SOURCE_DIR;
const fs::path kGridfree = fs::path(GRIDFREE_BIN_DIR) / "gridfree";
const fs::path kFake = kSource / "tests/fixtures/fake_worker.sh";

fs::path temp_dir(const std::string& name) { return gridfree::test_support::fresh_scratch_dir("cli_test", name); }

// Single-quoted for the shell ('\'' inside).
using gridfree::test_support::shell_quote;
std::string quote(const std::string& s) { return shell_quote(s); }

struct Output {
  int code = -1;
  std::string text;
};

// Runs a shell command line in `dir` with the fake worker; stdout+stderr.
Output run(const fs::path& dir, const std::string& args, const std::string& env = "") {
  const std::string cmd = "cd " + quote(dir.string()) + " && GRIDFREE_WORKER=" + quote(kFake.string()) + " " + env +
                          " " + quote(kGridfree.string()) + " " + args + " 2>&1";
  Output out;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out.text += buf;
  const int status = pclose(p);
  out.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string sql(const fs::path& db, const std::string& query) {
  const std::string cmd = "sqlite3 " + quote(db.string()) + " " + quote(query) + " 2>&1";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
  pclose(p);
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

// A study with one series per case name (the fake worker's mode) on 4 grids.
fs::path write_study(const fs::path& dir, const std::string& name, const std::vector<std::string>& cases) {
  std::ifstream in(kSource / "studies/quickstart.json");
  auto doc = nlohmann::json::parse(in);
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

pid_t spawn(const fs::path& dir, const std::vector<std::string>& args, const std::string& env_sleep) {
  std::vector<std::string> words = {"/bin/sh", "-c",
                                    "cd " + quote(dir.string()) + " && GRIDFREE_WORKER=" + quote(kFake.string()) +
                                        " GRIDFREE_FAKE_SLEEP=" + env_sleep + " exec " + quote(kGridfree.string())};
  for (const auto& a : args) words[2] += " " + quote(a);
  words[2] += " >" + quote((dir / "spawned.log").string()) + " 2>&1";
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
  return pid;
}

int results_count(const fs::path& db) {
  const auto s = sql(db, "SELECT COUNT(*) FROM results");
  return s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) ? 0 : std::stoi(s);
}

bool wait_until(const std::function<bool()>& done, double limit_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (std::chrono::steady_clock::now() < until) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

TEST(OrchestratorCli, ValidateAndPlanTheShippedStudies) {
  const auto dir = temp_dir("validate");
  auto out = run(dir, "validate " + quote((kSource / "studies/quickstart.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_NE(out.text.find("ok: 2 series, 10 jobs"), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("warning"), std::string::npos) << out.text;  // 5 grids, finest Δ* 0.667
  out = run(dir, "validate " + quote((kSource / "studies/bursting_bubble_paper.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_NE(out.text.find("ok: 12 series, 216 jobs"), std::string::npos) << out.text;
  out = run(dir, "plan --json " + quote((kSource / "studies/quickstart.json").string()));
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_EQ(nlohmann::json::parse(out.text)["jobs"], 10);
  EXPECT_FALSE(fs::exists(dir / "gridfree.sqlite"));
}

// validate and plan warn (exit 0) about grids that cannot give a converged
// verdict: 4 grids (1 degree of freedom), all coarser than Δ* = 2.
TEST(OrchestratorCli, ValidateAndPlanWarnAboutCoarseOrFewGrids) {
  const auto dir = temp_dir("warn");
  std::ifstream in(kSource / "studies/quickstart.json");
  auto doc = nlohmann::json::parse(in);
  doc["grids"] = {{"delta_star", {4.0, 3.3, 2.8, 2.5}}};
  const auto file = dir / "coarse.json";
  std::ofstream(file) << doc.dump(2);
  for (const char* cmd : {"validate ", "plan "}) {
    const auto out = run(dir, cmd + quote(file.string()));
    EXPECT_EQ(out.code, 0) << out.text;
    EXPECT_NE(out.text.find("warning: 4 grid(s) leave 1 degree(s) of freedom"), std::string::npos) << out.text;
    EXPECT_NE(out.text.find("warning: every grid is coarser than Δ* = 2"), std::string::npos) << out.text;
  }
}

TEST(OrchestratorCli, BrokenStudiesExitTwoNameThePointerAndLeaveNoDatabase) {
  const auto corpus = kSource / "tests/fixtures/broken_studies";
  std::ifstream in(corpus / "expected_pointers.json");
  const auto expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 15u);
  const auto dir = temp_dir("broken");
  // An existing database must not change either.
  const auto good = write_study(dir, "good", {"ok"});
  ASSERT_EQ(run(dir, "submit " + quote(good.string()) + " --db existing.sqlite").code, 0);
  const std::string before = sql(dir / "existing.sqlite", "SELECT COUNT(*), MAX(id) FROM studies") +
                             sql(dir / "existing.sqlite", "SELECT COUNT(*) FROM jobs");
  for (const auto& [file, pointer] : expected.items()) {
    const std::string study = quote((corpus / file).string());
    for (const std::string cmd : {"validate ", "run ", "submit "}) {
      const std::string db = cmd == "validate " ? "" : " --db new.sqlite";
      const auto out = run(dir, cmd + study + db);
      EXPECT_EQ(out.code, 2) << cmd << file << "\n" << out.text;
      EXPECT_NE(out.text.find(pointer.get<std::string>()), std::string::npos)
          << cmd << file << " should name " << pointer << ":\n" << out.text;
    }
    EXPECT_EQ(run(dir, "run " + study + " --db existing.sqlite").code, 2) << file;
    EXPECT_FALSE(fs::exists(dir / "new.sqlite")) << file;
    EXPECT_FALSE(fs::exists(dir / "gridfree.sqlite")) << file;
  }
  EXPECT_EQ(sql(dir / "existing.sqlite", "SELECT COUNT(*), MAX(id) FROM studies") +
                sql(dir / "existing.sqlite", "SELECT COUNT(*) FROM jobs"),
            before);
}

TEST(OrchestratorCli, RunRecordsEveryOutcomeRetriesOnceAndReusesOnRerun) {
  const auto dir = temp_dir("run");
  const auto study = write_study(dir, "mixed", {"ok", "noconv", "flaky", "crash"});
  const std::string log = (dir / "solves.log").string();
  auto out = run(dir, "run " + quote(study.string()) + " -j 2 --db g.sqlite", "GRIDFREE_FAKE_LOG=" + quote(log));
  EXPECT_EQ(out.code, 3) << out.text;  // some jobs did not converge
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM results"), "16");
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM results WHERE status = 'converged'"), "8");  // ok + flaky
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM results WHERE status = 'not_converged'"), "4");
  EXPECT_EQ(sql(db, "SELECT MAX(attempts) FROM jobs j JOIN results r ON r.job_id = j.id WHERE r.status = 'failed'"), "2");
  EXPECT_EQ(sql(db, "SELECT status FROM studies"), "failed");
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM series WHERE status = 'done'"), "4");
  // ok's dp* is 1159 + Δ* exactly (fake worker): the extrapolated f0 is 1159.
  const auto f0 = sql(db, "SELECT e.f0 FROM extrapolations e JOIN series s ON s.id = e.series_id "
                          "WHERE s.case_name = 'ok' AND e.chosen = 1");
  ASSERT_FALSE(f0.empty()) << sql(db, "SELECT * FROM extrapolations");
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
  out = run(dir, "run " + quote(study.string()) + " -j 2 --db g.sqlite", "GRIDFREE_FAKE_LOG=" + quote(log));
  EXPECT_EQ(out.code, 3) << out.text;
  EXPECT_EQ(lines(), 24);  // nothing ran again
  out = run(dir, "status mixed --db g.sqlite --json");
  EXPECT_EQ(out.code, 0) << out.text;
  const auto st = nlohmann::json::parse(out.text);
  EXPECT_EQ(st[0]["converged"], 8);
  EXPECT_EQ(st[0]["failed"], 8);
  EXPECT_EQ(sql(db, "PRAGMA integrity_check"), "ok");
}

TEST(OrchestratorCli, KillMinusNineThenRerunCompletesWithoutDuplicates) {
  const auto dir = temp_dir("kill9");
  const auto study = write_study(dir, "killme", {"ok", "ok2"});
  const auto db = dir / "g.sqlite";
  const pid_t pid = spawn(dir, {"run", study.string(), "-j", "2", "--db", "g.sqlite"}, "0.4");
  ASSERT_TRUE(wait_until([&] { return results_count(db) >= 2; }, 60));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_LT(results_count(db), 8);
  const auto out = run(dir, "run " + quote(study.string()) + " -j 2 --db g.sqlite", "GRIDFREE_FAKE_SLEEP=0.05");
  EXPECT_EQ(out.code, 0) << out.text;
  EXPECT_EQ(sql(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "8|8");
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM jobs WHERE status <> 'done'"), "0");
  EXPECT_EQ(sql(db, "SELECT status FROM studies"), "done");
  EXPECT_EQ(sql(db, "PRAGMA integrity_check"), "ok");
}

TEST(OrchestratorCli, DaemonStopsOnSigtermAndARestartFinishesTheQueue) {
  const auto dir = temp_dir("daemon");
  const auto study = write_study(dir, "queued", {"ok", "ok2", "ok3"});
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(run(dir, "submit " + quote(study.string()) + " --db g.sqlite").code, 0);
  pid_t pid = spawn(dir, {"daemon", "-j", "2", "--db", "g.sqlite"}, "0.4");
  ASSERT_TRUE(wait_until([&] { return results_count(db) >= 2; }, 60));
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_TRUE(wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 10));
  EXPECT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(sql(db, "SELECT COUNT(*) FROM jobs WHERE status = 'running'"), "0");  // released
  EXPECT_LT(results_count(db), 12);
  pid = spawn(dir, {"daemon", "-j", "2", "--db", "g.sqlite"}, "0.05");
  ASSERT_TRUE(wait_until([&] { return sql(db, "SELECT status FROM studies") == "done"; }, 60));
  kill(pid, SIGINT);
  ASSERT_TRUE(wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 10));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(sql(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "12|12");
  EXPECT_EQ(sql(db, "PRAGMA integrity_check"), "ok");
}

}  // namespace
