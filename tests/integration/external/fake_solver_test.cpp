// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree-worker solve` and `collect` on external jobs run by a fake
// solver (tests/fixtures/external/fake_solver/solver.sh): every
// classification rule end to end with the reason in the result, the
// command's own result file, template and job-document refusals, and a stop
// (SIGTERM to the worker or to its group) that ends the command and its
// child with exit 130 and no result, the progress file written meanwhile.
// No OpenFOAM needed.
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "job/template_hash.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"

extern char** environ;

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kFakeTemplate = fs::path(GRIDFREE_SOURCE_DIR) / "tests/fixtures/external/fake_solver";
const std::string kWorker = std::string(GRIDFREE_BIN_DIR) + "/gridfree-worker";

json fake_job(const fs::path& template_dir, int mode, int n) {
  return {{"schema", "gridfree/job/1"},
          {"case",
           {{"name", "fake"},
            {"external",
             {{"template_dir", template_dir.string()},
              {"template_sha256", template_sha256(template_dir)},
              {"render", {"params"}},
              {"variables", {{"mode", mode}, {"N", n}}},
              {"setup", {"export FAKE_SETUP=1"}},
              {"command", {"./solver.sh"}},
              {"version", "fake 1.0"},
              {"collect",
               {{"quantities", {{"q", {{"units", "1"}, {"file", "post/*/0/q.dat"}, {"column", 1}}}}},
                {"failure_patterns", {"FOAM FATAL"}},
                {"residual", {{"log", "log.solver"}, {"regex", "Ux residual = ([-+0-9.eE]+)"}, {"tolerance", 1e-6}}},
                {"steady_tolerance", 1e-9}}}}}}},
          {"numerics", {{"grid", {{"level", 0}, {"h", 1.0 / n}, {"cells", n * n}}}}}};
}

struct FakeRun {
  int code = -1;
  json result;  // null when none was written
  fs::path dir;
  std::string err;
};

FakeRun run_fake(const std::string& name, const json& job, const std::string& verb = "solve") {
  FakeRun r;
  r.dir = test_support::fresh_scratch_dir("external_fake", name);
  test_support::save_json(r.dir / "job.json", job);
  const auto ran = test_support::run_executable(
      "gridfree-worker", verb + " " + (r.dir / "job.json").string() + " -o " + (r.dir / "result.json").string() + " -q",
      r.dir);
  r.code = ran.exit_code;
  r.err = ran.err;
  if (fs::exists(r.dir / "result.json")) r.result = test_support::load_json(r.dir / "result.json");
  return r;
}

std::string fake_reason(const FakeRun& r) { return r.result.is_object() ? r.result.value("reason", "") : "(no result) " + r.err; }

TEST(ExternalFakeSolver, ConvergedWithTheQuantityTimingsAndLogs) {
  const auto r = run_fake("converged", fake_job(kFakeTemplate, 0, 4));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.result["status"], "converged") << fake_reason(r);
  EXPECT_DOUBLE_EQ(r.result["quantities"]["q"].get<double>(), 1.0625);
  EXPECT_DOUBLE_EQ(r.result["grid"]["h"].get<double>(), 0.25);
  EXPECT_EQ(r.result["extra"]["exit_code"], 0);
  EXPECT_EQ(r.result["extra"]["external_version"], "fake 1.0");
  EXPECT_TRUE(r.result["srq"]["dp_star"].is_null());
  EXPECT_GT(r.result["timing"]["wall_s"].get<double>(), 0);
  EXPECT_GT(r.result["memory"]["peak_rss_mb"].get<double>(), 0);  // the children's, from wait4
  EXPECT_NE(test_support::slurp(r.dir / "case/stdout.log").find("fake solver: mode 0, N 4"), std::string::npos);
  EXPECT_EQ(test_support::slurp(r.dir / "case/params"), "MODE=0\nN=4\n");  // rendered in the copy
  EXPECT_EQ(test_support::slurp(kFakeTemplate / "params"), "MODE=@@mode@@\nN=@@N@@\n");  // template untouched
}

TEST(ExternalFakeSolver, EachFailureRuleWithItsReason) {
  struct Case {
    int mode;
    const char* status;
    const char* outcome;
    const char* reason;
  };
  const Case cases[] = {
      {1, "failed", "failed",
       "failure pattern \"FOAM FATAL\" at line 3 of log.solver: --> FOAM FATAL IO ERROR: | keyword deltaT is undefined"},
      {2, "failed", "failed", "exit code 3"},
      {3, "failed", "failed", "quantity q missing: no file matches post/*/0/q.dat in the case folder"},
      {4, "failed", "failed",
       "quantity q missing: \"garbage\" in column 1 of the last row is not a number in post/q/0/q.dat"},
      {5, "diverged", "diverged", "quantity q is nan in post/q/0/q.dat"},
      {6, "not_converged", "stalled", "residual 0.02 above the tolerance 1e-06 (last value in log.solver)"},
      {7, "not_converged", "iteration_cap",
       "quantity q still changing: 0.292 between the last two records of post/q/0/q.dat (steady_tolerance 1e-09)"},
      {10, "failed", "failed", "killed by SIGSEGV"},
  };
  for (const auto& c : cases) {
    const auto r = run_fake("mode" + std::to_string(c.mode), fake_job(kFakeTemplate, c.mode, 4));
    EXPECT_EQ(r.code, 3) << "mode " << c.mode << ": " << r.err;
    EXPECT_EQ(r.result.value("status", ""), c.status) << "mode " << c.mode;
    EXPECT_EQ(r.result.value("outcome", ""), c.outcome) << "mode " << c.mode;
    EXPECT_EQ(fake_reason(r), c.reason) << "mode " << c.mode;
  }
}

// A command that sends a program's output to a log of its own (`blockMesh
// > log.blockMesh 2>&1 && ...`): the failure pattern is found there, as in
// every log.* / *.log file of the case, and the reason carries stderr's
// tail; a file of another name is searched when collect.logs names it.
TEST(ExternalFakeSolver, FailurePatternInALogTheCommandNamesItself) {
  auto r = run_fake("own_log", fake_job(kFakeTemplate, 11, 4));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(r.result.value("status", ""), "failed");
  EXPECT_EQ(fake_reason(r),
            "failure pattern \"FOAM FATAL\" at line 3 of log.mesher: --> FOAM FATAL ERROR: | cannot find file "
            "\"system/blockMeshDict\" (stderr: mesher: setting up | mesher: giving up)");

  auto job = fake_job(kFakeTemplate, 12, 4);
  r = run_fake("unnamed_file", job);
  EXPECT_EQ(fake_reason(r), "exit code 1") << "run/solver.out is no log by its name and not named";
  job["case"]["external"]["collect"]["logs"] = {"run/*.out"};
  r = run_fake("named_file", job);
  EXPECT_EQ(fake_reason(r),
            "failure pattern \"FOAM FATAL\" at line 2 of run/solver.out: --> FOAM FATAL ERROR: Maximum number of "
            "iterations exceeded");
  job["case"]["external"]["collect"]["logs"] = {"../outside.log"};
  r = run_fake("outside_log", job);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/case/external/collect/logs/0"), std::string::npos) << r.err;
}

TEST(ExternalFakeSolver, CommandNotFoundOrNotExecutable) {
  auto job = fake_job(kFakeTemplate, 0, 4);
  job["case"]["external"]["command"] = {"no_such_solver_gridfree"};
  auto r = run_fake("not_found", job);
  EXPECT_EQ(r.code, 3);
  // The shell's own words follow (dash: "gridfree-setup: 3: exec: no_such_solver_gridfree: not found").
  EXPECT_EQ(fake_reason(r).rfind("command not found (exit code 127) (stderr: ", 0), 0u) << fake_reason(r);
  EXPECT_NE(fake_reason(r).find("no_such_solver_gridfree"), std::string::npos) << fake_reason(r);
  job["case"]["external"].erase("setup");  // exec'd by the worker itself
  r = run_fake("not_found_direct", job);
  EXPECT_EQ(fake_reason(r),
            "command not found (exit code 127) (stderr: gridfree-worker: no_such_solver_gridfree: command not found)");
  job["case"]["external"]["command"] = {"./params"};  // not executable
  r = run_fake("not_executable", job);
  EXPECT_EQ(r.result.value("status", ""), "failed");
  EXPECT_EQ(fake_reason(r).rfind("command not executable (exit code 126)", 0), 0u) << fake_reason(r);
}

TEST(ExternalFakeSolver, TheCommandsOwnResultFile) {
  auto job = fake_job(kFakeTemplate, 9, 4);
  job["case"]["external"]["collect"]["quantities"]["q"] = {{"file", "nowhere.dat"}, {"column", 0}};
  const auto r = run_fake("own_result", job);
  ASSERT_EQ(r.code, 0) << fake_reason(r);
  EXPECT_DOUBLE_EQ(r.result["quantities"]["q"].get<double>(), 1.0625);  // from the file, not nowhere.dat
  EXPECT_DOUBLE_EQ(r.result["quantities"]["own"].get<double>(), 42);
}

TEST(ExternalFakeSolver, TemplateEditedAfterPlanningIsRefused) {
  const auto tmpl = test_support::fresh_scratch_dir("external_fake", "edited_template");
  fs::copy(kFakeTemplate, tmpl, fs::copy_options::recursive);
  const auto job = fake_job(tmpl, 0, 4);
  std::ofstream(tmpl / "params", std::ios::app) << "# edited\n";
  const auto r = run_fake("edited", job);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.result.value("status", ""), "failed");
  EXPECT_EQ(fake_reason(r).rfind("template changed since the job was planned", 0), 0u) << fake_reason(r);
  EXPECT_FALSE(fs::exists(r.dir / "case")) << "nothing was run";
}

TEST(ExternalFakeSolver, InvalidJobsExitTwoNamingThePath) {
  auto job = fake_job(kFakeTemplate, 0, 4);
  job["case"]["external"]["variables"].erase("mode");
  auto r = run_fake("undefined_placeholder", job);
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(r.result.is_null());
  EXPECT_NE(r.err.find("/case/external/render/0: params:1: @@mode@@ is not a variable (variables: N, cores)"),
            std::string::npos)
      << r.err;
  job = fake_job(kFakeTemplate, 0, 4);
  job["case"]["external"]["collect"]["quantities"]["q"]["column"] = "one";
  r = run_fake("bad_column", job);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/case/external/collect/quantities/q/column"), std::string::npos) << r.err;
}

TEST(ExternalFakeSolver, CollectRereadsWithoutRunning) {
  auto r = run_fake("collect", fake_job(kFakeTemplate, 0, 4));
  ASSERT_EQ(r.code, 0) << r.err;
  const json first = r.result;
  // The case is not run again: a marker left in it survives, and a changed
  // collect section (a steady tolerance the records fail) is applied.
  std::ofstream(r.dir / "case" / "marker") << "x";
  auto job = fake_job(kFakeTemplate, 0, 4);
  test_support::save_json(r.dir / "job.json", job);
  const auto again = test_support::run_executable(
      "gridfree-worker", "collect " + (r.dir / "job.json").string() + " -o " + (r.dir / "again.json").string() + " -q",
      r.dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const json second = test_support::load_json(r.dir / "again.json");
  EXPECT_EQ(second["quantities"], first["quantities"]);
  EXPECT_EQ(second["status"], first["status"]);
  EXPECT_EQ(second["timing"], first["timing"]);  // from case/.gridfree_exit
  EXPECT_TRUE(fs::exists(r.dir / "case" / "marker"));
  // A failed run re-collects as failed: its exit code is recorded.
  auto failed = run_fake("collect_failed", fake_job(kFakeTemplate, 2, 4));
  const auto recollected = test_support::run_executable(
      "gridfree-worker", "collect " + (failed.dir / "job.json").string() + " -q", failed.dir);
  EXPECT_EQ(recollected.exit_code, 3);
  EXPECT_NE(recollected.out.find("\"reason\": \"exit code 3\""), std::string::npos) << recollected.out;
}

// The worker started on the side (its own process group when `leader`, as
// the orchestrator starts it), stopped with SIGTERM once the fake solver has
// started its child.
void stop_fake_run(const std::string& name, bool leader) {
  const auto dir = test_support::fresh_scratch_dir("external_fake", name);
  test_support::save_json(dir / "job.json", fake_job(kFakeTemplate, 8, 4));
  const std::string job = (dir / "job.json").string(), out = (dir / "result.json").string();
  const std::string progress = (dir / "progress.json").string();
  const char* argv[] = {kWorker.c_str(), "solve", job.c_str(), "-o", out.c_str(), "--progress", progress.c_str(), "-q",
                        nullptr};
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  if (leader) {
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0);
  }
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, kWorker.c_str(), nullptr, &attr, const_cast<char* const*>(argv), environ), 0);
  posix_spawnattr_destroy(&attr);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (!fs::exists(dir / "case" / "started") && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(dir / "case" / "started"));
  const pid_t child = std::stoi(test_support::slurp(dir / "case" / "child.pid"));
  // While it runs, the progress file says how long (every ~2 s; what
  // `gridfree status` reads).
  const auto progress_by = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!fs::exists(dir / "progress.json") && std::chrono::steady_clock::now() < progress_by)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(dir / "progress.json"));
  const json p = test_support::load_json(dir / "progress.json");
  EXPECT_GT(p["elapsed_s"].get<double>(), 1.0);
  EXPECT_EQ(p["pid"].get<long long>(), static_cast<long long>(pid));
  const auto sent = std::chrono::steady_clock::now();
  ASSERT_EQ(leader ? ::kill(-pid, SIGTERM) : ::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_LT(took, 5.0) << "the stop waited for the 60 s sleep";
  EXPECT_FALSE(fs::exists(dir / "result.json"));
  // The solver's own child (sleep 60) is gone too (reaped by init shortly).
  const auto gone_by = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (::kill(child, 0) == 0 && std::chrono::steady_clock::now() < gone_by)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_NE(::kill(child, 0), 0) << "the solver's child " << child << " outlived the stop";
  // The stopped case's files are partial: collecting them is a failure.
  const auto collected = test_support::run_executable("gridfree-worker", "collect " + job + " -q", dir);
  EXPECT_EQ(collected.exit_code, 3);
  EXPECT_NE(collected.out.find("no record of how the command ended"), std::string::npos) << collected.out;
}

TEST(ExternalFakeSolver, StopBySigtermToTheWorker) { stop_fake_run("stop_worker", false); }

TEST(ExternalFakeSolver, StopBySigtermToTheWorkersGroup) { stop_fake_run("stop_group", true); }

}  // namespace
}  // namespace gridfree
