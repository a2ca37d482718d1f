// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run --executor slurm` against a real single-node Slurm
// (tests/integration/slurm/slurm_cluster.sh: munged + slurmctld + slurmd from
// Debian, started per test in a scratch folder) with the fake worker
// (tests/fixtures/fake_worker.sh). Every run of a job is counted twice over:
// by the fake worker (GRIDFREE_FAKE_LOG: one line per solve) and by Slurm's
// own job-completion log (jobcomp/filetxt). Skipped, with the reason, where
// the daemons cannot run (not root, or Slurm not installed:
// scripts/install-deps.sh test installs it).
#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "openfoam_mpi_study.h"
#include "openfoam_present.h"
#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::run_command;
using gridfree::test_support::kFakeWorker;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::kSourceDir;
using gridfree::test_support::quickstart_document;
const fs::path kCluster = kSourceDir / "tests/integration/slurm/slurm_cluster.sh";

using gridfree::test_support::shell_quote;

std::vector<std::string> lines_of(const fs::path& file) {
  std::vector<std::string> out;
  std::ifstream in(file);
  for (std::string l; std::getline(in, l);)
    if (!l.empty()) out.push_back(l);
  return out;
}

bool wait_until(const std::function<bool()>& done, double limit_s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  while (std::chrono::steady_clock::now() < until) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return done();
}

class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    if (geteuid() != 0) GTEST_SKIP() << "the Slurm daemons need root (slurmd starts jobs as their user)";
    if (std::system("command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null") != 0)
      GTEST_SKIP() << "slurmctld/slurmd/munged not installed (scripts/install-deps.sh test)";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = gridfree::test_support::fresh_scratch_dir("slurm_test", info->name());
    cluster_ = dir_ / "cluster";
    work_ = dir_ / "with space";  // every path the batch script sees has a space in it
    fs::create_directories(work_);
    started_ = true;  // TearDown stops whatever did start
    const auto r =
        run_command(shell_quote(kCluster.string()) + " start " + shell_quote(cluster_.string()), dir_ / "start.err");
    ASSERT_EQ(r.exit_code, 0) << "cluster did not start: " << r.err;
    setenv("SLURM_CONF", (cluster_ / "slurm.conf").c_str(), 1);
    setenv("GRIDFREE_WORKER", kFakeWorker.c_str(), 1);
    setenv("GRIDFREE_FAKE_LOG", (dir_ / "solves.log").c_str(), 1);
    unsetenv("GRIDFREE_FAKE_SLEEP");
  }
  void TearDown() override {
    for (pid_t pid : spawned_)
      if (waitpid(pid, nullptr, WNOHANG) == 0) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
      }
    if (started_) std::system((shell_quote(kCluster.string()) + " stop " + shell_quote(cluster_.string())).c_str());
  }

  fs::path db() const { return work_ / "g.sqlite"; }

  // gridfree ARGS in the work folder; stdout + stderr.
  gridfree::test_support::CommandRun gridfree(const std::string& args, const std::string& env = "") {
    return run_command("cd " + shell_quote(work_.string()) + " && " + env + " " + shell_quote(kGridfreeExe.string()) +
                           " " + args + " 2>&1",
                       dir_ / "gridfree.err");
  }

  pid_t spawn_gridfree(const std::string& args, const std::string& env) {
    std::string line = "cd " + shell_quote(work_.string()) + " && " + env + " exec " +
                       shell_quote(kGridfreeExe.string()) + " " + args + " >>" +
                       shell_quote((dir_ / "spawned.log").string()) + " 2>&1";
    std::vector<std::string> words = {"/bin/sh", "-c", line};
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
    spawned_.push_back(pid);
    return pid;
  }

  std::string sql(const std::string& query) {
    auto r = run_command("sqlite3 " + shell_quote(db().string()) + " " + shell_quote(query), dir_ / "sql.err");
    while (!r.out.empty() && r.out.back() == '\n') r.out.pop_back();
    return r.out;
  }
  int count(const std::string& query) {
    const auto s = sql(query);
    return s.empty() || !std::isdigit(static_cast<unsigned char>(s[0])) ? -1 : std::stoi(s);
  }

  // A study of `cases` (the fake worker's modes) on four grids each.
  fs::path study(const std::string& name, const std::vector<std::string>& cases,
               const nlohmann::json& slurm = nullptr) {
    auto doc = quickstart_document();
    doc["name"] = name;
    const auto pc1 = doc["cases"]["PC1"];
    doc["cases"] = nlohmann::json::object();
    for (const auto& c : cases) doc["cases"][c] = pc1;
    doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
    doc["design"] = "factorial";
    doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.5}}};
    if (!slurm.is_null()) doc["slurm"] = slurm;
    const auto file = work_ / (name + ".json");
    std::ofstream(file) << doc.dump(2);
    return file;
  }

  // Solves per run folder, from the fake worker's log.
  std::map<std::string, int> solves() {
    std::map<std::string, int> n;
    for (const auto& l : lines_of(dir_ / "solves.log")) ++n[l.substr(0, l.rfind(' '))];
    return n;
  }
  // Slurm's own record: jobs that ended, by "JobId=<id>" (array tasks included).
  int slurm_jobs_ended(const std::string& state = "") {
    int n = 0;
    for (const auto& l : lines_of(cluster_ / "jobcomp.log"))
      if (state.empty() || l.find("JobState=" + state + " ") != std::string::npos) ++n;
    return n;
  }
  void expect_each_job_solved_once(int jobs) {
    const auto s = solves();
    EXPECT_EQ(static_cast<int>(s.size()), jobs);
    for (const auto& [run_dir, n] : s) EXPECT_EQ(n, 1) << run_dir << " solved " << n << " times";
  }

  fs::path dir_, cluster_, work_;
  bool started_ = false;
  std::vector<pid_t> spawned_;
};

TEST_F(SlurmCluster, ArraysGiveTheLocalExecutorsResultsAndQuoteEveryPath) {
  const auto file = study("same", {"ok_a", "ok_b"});
  auto r =
      gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm -j 3");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 8);
  expect_each_job_solved_once(8);
  EXPECT_EQ(slurm_jobs_ended("COMPLETED"), 8);
  // All eight in one array: one batch script, task ids 0..7.
  int scripts = 0;
  for (const auto& e : fs::directory_iterator(work_ / "g.sqlite.runs" / "slurm"))
    scripts += e.path().extension() == ".sbatch";
  EXPECT_EQ(scripts, 1);
  EXPECT_EQ(count("SELECT COUNT(DISTINCT substr(external_id, 1, instr(external_id, '_'))) FROM jobs"), 1);
  // The same study with the local executor: identical dp* to the last digit.
  const auto slurm_dp = sql("SELECT j.job_hash, quote(r.dp_star) FROM results r JOIN jobs j ON j.id = r.job_id ORDER BY 1");
  fs::rename(db(), work_ / "slurm.sqlite");
  r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " -j 2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(sql("SELECT j.job_hash, quote(r.dp_star) FROM results r JOIN jobs j ON j.id = r.job_id ORDER BY 1"),
            slurm_dp);
}

// A cores rule (study/job_cores.h): the finest grid (12 x 80 x 4 = 3 840
// cells, 2.02 by the rule) gets 2 cores, the others (480, 800, 1 647) one;
// each core count is its own array, and Slurm allocated each job its cores.
TEST_F(SlurmCluster, ACoresRuleGivesEachArrayItsJobsCores) {
  const auto file = study("cores", {"ok_a"});
  auto doc = nlohmann::json::parse(std::ifstream(file));
  doc["cores"] = "max(1, cells / 1900)";
  std::ofstream(file) << doc.dump(2);
  const auto r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) +
                          " --executor slurm --cpus-per-task 2 -j 4");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
  int scripts = 0;
  for (const auto& e : fs::directory_iterator(work_ / "g.sqlite.runs" / "slurm"))
    scripts += e.path().extension() == ".sbatch";
  EXPECT_EQ(scripts, 2);
  std::map<std::string, int> by_procs;  // Slurm's own record of each job's CPUs
  for (const auto& l : lines_of(cluster_ / "jobcomp.log")) {
    const auto at = l.find("ProcCnt=");
    if (at != std::string::npos) ++by_procs[l.substr(at + 8, l.find(' ', at) - at - 8)];
  }
  EXPECT_EQ(by_procs["1"], 3);
  EXPECT_EQ(by_procs["2"], 1);
}

// The OpenFOAM cavity whose 20² grid gets 2 cores by the cores rule
// (tests/support/openfoam_mpi_study.h; the local pool's run of it:
// tests/integration/external/openfoam_mpi_test.cpp): its array asks 2 tasks,
// Slurm allocates them (jobcomp ProcCnt=2), and mpirun runs icoFoam on 2
// ranks inside the allocation (processor0 and processor1 in its run folder).
TEST_F(SlurmCluster, AnOpenFoamStudysFinestGridRunsOnTwoMpiRanksInItsOwnArray) {
  ASSERT_TRUE(gridfree::test_support::openfoam_present()) << "OpenFOAM is not installed: scripts/install-deps.sh test";
  // OpenFOAM refuses a case path with a space (fileName::stripInvalid), so
  // this study and its run folders live beside the work folder, not in it.
  const fs::path here = dir_ / "openfoam";
  fs::create_directories(here);
  const auto file = gridfree::test_support::write_openfoam_mpi_study(here, "cavity_mpi", true);
  const std::string worker = (fs::path(GRIDFREE_BIN_DIR) / "gridfree-worker").string();
  const auto r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote((here / "g.sqlite").string()) +
                              " --executor slurm --cpus-per-task 2 -j 4",
                          "GRIDFREE_WORKER=" + shell_quote(worker));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto sql_here = [&](const std::string& q) {
    auto out = run_command("sqlite3 " + shell_quote((here / "g.sqlite").string()) + " " + shell_quote(q),
                           dir_ / "sql.err").out;
    while (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
  };
  EXPECT_EQ(sql_here("SELECT COUNT(*) FROM results WHERE status = 'converged'"), "3");
  std::map<std::string, int> by_procs;
  for (const auto& l : lines_of(cluster_ / "jobcomp.log")) {
    const auto at = l.find("ProcCnt=");
    if (at != std::string::npos) ++by_procs[l.substr(at + 8, l.find(' ', at) - at - 8)];
  }
  EXPECT_EQ(by_procs["1"], 2);
  EXPECT_EQ(by_procs["2"], 1);
  const std::string hash = sql_here("SELECT job_hash FROM jobs WHERE abs(delta_star - 0.1 / " +
                                    std::to_string(gridfree::test_support::kMpiFinestN) + ") < 1e-12");
  ASSERT_EQ(hash.size(), 64u) << hash;
  int decomposed = 0;
  for (const auto& e : fs::recursive_directory_iterator(here / "g.sqlite.runs"))
    if (e.is_directory() && e.path().filename() == "processor1") {
      ++decomposed;
      EXPECT_EQ(e.path().parent_path().parent_path().filename(), hash);  // <hash>/case/processor1
    }
  EXPECT_EQ(decomposed, 1);
}

TEST_F(SlurmCluster, KillNineThenRerunAdoptsEveryJobAndRunsEachOnce) {
  const auto file = study("adopt", {"ok_a", "ok_b"});
  const std::string args =
      "run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm -j 2";
  const pid_t pid = spawn_gridfree(args, "GRIDFREE_FAKE_SLEEP=1.5");
  // Two done, two running, four pending: then the orchestrator dies.
  ASSERT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM results") >= 2; }, 60));
  // `status` shows Slurm's ids, states and reasons (as last polled).
  std::string shown;
  EXPECT_TRUE(wait_until(
      [&] {
        shown = gridfree("status adopt --db " + shell_quote(db().string())).out;
        return shown.find("RUNNING") != std::string::npos && shown.find("JobArrayTaskLimit") != std::string::npos;
      },
      10))
      << shown;
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  const int recorded = count("SELECT COUNT(*) FROM results");
  EXPECT_LT(recorded, 8);
  // While nobody watches, the running ones finish and the next ones start.
  ASSERT_TRUE(wait_until([&] { return slurm_jobs_ended() >= recorded + 2; }, 30));
  const auto r = gridfree(args, "GRIDFREE_FAKE_SLEEP=1.5");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE((r.out + r.err).find("adopted"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 8);
  expect_each_job_solved_once(8);
  EXPECT_EQ(slurm_jobs_ended(), 8);  // Slurm ran 8 jobs, not 8 + resubmissions
  EXPECT_EQ(count("SELECT MAX(attempts) FROM jobs"), 1);
}

TEST_F(SlurmCluster, AKilledDaemonsJobsAreAdoptedByTheNextDaemon) {
  const auto file = study("daemon", {"ok_a", "ok_b"});
  ASSERT_EQ(gridfree("submit " + shell_quote(file.string()) + " --db " + shell_quote(db().string())).exit_code, 0);
  const std::string args = "daemon --db " + shell_quote(db().string()) + " --executor slurm -j 2";
  const pid_t first = spawn_gridfree(args, "GRIDFREE_FAKE_SLEEP=1");
  ASSERT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM results") >= 2; }, 60));
  kill(first, SIGKILL);
  waitpid(first, nullptr, 0);
  const pid_t second = spawn_gridfree(args, "GRIDFREE_FAKE_SLEEP=1");
  EXPECT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM results") == 8; }, 60));
  kill(second, SIGTERM);
  int status = 0;
  EXPECT_TRUE(wait_until([&] { return waitpid(second, &status, WNOHANG) == second; }, 20));
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 8);
  expect_each_job_solved_once(8);
  EXPECT_EQ(slurm_jobs_ended(), 8);
}

TEST_F(SlurmCluster, JobsSubmittedButNotRecordedAreFoundInTheQueue) {
  const auto file = study("unrecorded", {"ok_a"});
  const std::string args =
      "run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm -j 1";
  const pid_t pid = spawn_gridfree(args, "GRIDFREE_FAKE_SLEEP=1");
  ASSERT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM results") >= 1; }, 60));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  // As if killed between sbatch's answer and the transaction recording it.
  sql("UPDATE jobs SET external_id = NULL WHERE status = 'running'");
  const auto r = gridfree(args, "GRIDFREE_FAKE_SLEEP=1");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
  expect_each_job_solved_once(4);
  EXPECT_EQ(slurm_jobs_ended(), 4);
}

TEST_F(SlurmCluster, JobsPurgedFromTheControllerAreResolvedFromTheRunFolder) {
  const auto file = study("purged", {"ok_a"});
  const std::string args =
      "run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm -j 4";
  const pid_t pid = spawn_gridfree(args, "GRIDFREE_FAKE_SLEEP=1");
  ASSERT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM jobs WHERE external_id LIKE 'slurm:%'") == 4; }, 30));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  ASSERT_TRUE(wait_until([&] { return slurm_jobs_ended() == 4; }, 30));
  // Ids the controller no longer knows (as after MinJobAge): squeue lists none of them.
  sql("UPDATE jobs SET external_id = 'slurm:999999' || substr(external_id, instr(external_id, '_'))");
  const auto r = gridfree(args);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
  expect_each_job_solved_once(4);
}

TEST_F(SlurmCluster, ControllerDownAtSubmitAndMidStudyCostsNoAttempt) {
  const auto file = study("outage", {"ok_a"});
  ASSERT_EQ(std::system((shell_quote(kCluster.string()) + " ctld-stop " + shell_quote(cluster_.string())).c_str()), 0);
  const pid_t pid = spawn_gridfree(
      "run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm -j 1",
      "GRIDFREE_FAKE_SLEEP=1");
  std::this_thread::sleep_for(std::chrono::seconds(3));  // sbatch fails: controller unreachable
  EXPECT_EQ(count("SELECT COUNT(*) FROM jobs WHERE external_id IS NOT NULL"), 0);
  ASSERT_EQ(std::system((shell_quote(kCluster.string()) + " ctld-start " + shell_quote(cluster_.string())).c_str()), 0);
  ASSERT_TRUE(wait_until([&] { return count("SELECT COUNT(*) FROM results") >= 1; }, 60));
  ASSERT_EQ(std::system((shell_quote(kCluster.string()) + " ctld-stop " + shell_quote(cluster_.string())).c_str()), 0);
  std::this_thread::sleep_for(std::chrono::seconds(3));  // squeue fails mid-study
  ASSERT_EQ(std::system((shell_quote(kCluster.string()) + " ctld-start " + shell_quote(cluster_.string())).c_str()), 0);
  int status = 0;
  ASSERT_TRUE(wait_until([&] { return waitpid(pid, &status, WNOHANG) == pid; }, 90));
  EXPECT_EQ(WEXITSTATUS(status), 0) << lines_of(dir_ / "spawned.log").size();
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
  EXPECT_EQ(count("SELECT MAX(attempts) FROM jobs"), 1);
  expect_each_job_solved_once(4);
}

// sbatch refusing the submission (a bad partition) is a configuration
// error: exit 2 with sbatch's words, the jobs back in the queue with no
// attempt spent, and the corrected command finishes them.
TEST_F(SlurmCluster, ABadPartitionIsAConfigurationErrorThatSpendsNoAttempt) {
  // The partition comes from the study's own "slurm" settings.
  const auto file = study("badpart", {"ok_a"}, {{"partition", "nope"}});
  auto r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) + " --executor slurm");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("Invalid partition name specified"), std::string::npos) << r.err;
  EXPECT_EQ(sql("SELECT status, attempts, COUNT(*) FROM jobs GROUP BY status, attempts"), "queued|0|4");
  EXPECT_EQ(count("SELECT COUNT(*) FROM results"), 0);
  EXPECT_TRUE(solves().empty());
  // A flag overrides the study (profile < study < flags).
  r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) +
               " --executor slurm --partition debug");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
  EXPECT_EQ(count("SELECT MAX(attempts) FROM jobs"), 1);
  expect_each_job_solved_once(4);
}

TEST_F(SlurmCluster, ANeverStartableJobFailsWithSlurmsReason) {
  const auto file = study("never", {"ok_a"});
  // Partition "short" allows 1 minute; the jobs ask for 5.
  const auto r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) +
                          " --executor slurm --partition short --time 5");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE reason LIKE '%Reason=PartitionTimeLimit%'"), 4)
      << sql("SELECT reason FROM results");
  EXPECT_TRUE(solves().empty());
  EXPECT_EQ(sql("SELECT COUNT(*) FROM jobs WHERE status = 'failed'"), "4");
}

TEST_F(SlurmCluster, TheTimeoutCountsRunTimeNotTimeInTheQueue) {
  // One at a time, 1.5 s each: the last waits ~5 s in the queue, longer than
  // the 3 s timeout, and must still converge.
  const auto file = study("queued", {"ok_a"});
  const auto r = gridfree("run " + shell_quote(file.string()) + " --db " + shell_quote(db().string()) +
                              " --executor slurm -j 1 --timeout 3",
                          "GRIDFREE_FAKE_SLEEP=1.5");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(count("SELECT COUNT(*) FROM results WHERE status = 'converged'"), 4);
}

// Bad settings are refused before anything is submitted or any database is
// made (no cluster needed).
TEST(SlurmSettingsCli, BadSettingsExitTwoNamingTheFieldAndLeaveNoDatabase) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("slurm_test", "settings");
  std::ofstream(dir / "profile.json") << R"({"partition": "p", "mem_gb": 4})";
  auto doc = quickstart_document();
  std::ofstream(dir / "plain.json") << doc.dump();
  doc["slurm"] = {{"partiton", "p"}};
  std::ofstream(dir / "misspelt.json") << doc.dump();
  const std::string db = " --db " + shell_quote((dir / "g.sqlite").string());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--executor slurm --slurm-profile " + shell_quote((dir / "profile.json").string()), "slurm-profile.mem_gb"},
      {"--executor slurm --slurm-profile " + shell_quote((dir / "missing.json").string()), "--slurm-profile"},
      {"--executor slurm --mem -5", "--mem"},
      {"--executor slurm --cpus-per-task 0", "--cpus-per-task"},
      {"--executor slurm --sbatch-arg=--array=1-9", "--sbatch-arg"},
      {"--executor pbs", "--executor"},
      {"--executor slurm --sbatch-arg=-o", "--sbatch-arg"},
      {"--partition debug", "--partition"}};  // a Slurm flag without --executor slurm
  for (const auto& [flags, field] : cases) {
    const auto file = dir / "plain.json";
    const auto r = run_command(
        shell_quote(kGridfreeExe.string()) + " run " + shell_quote(file.string()) + db + " " + flags, dir / "err.txt");
    EXPECT_EQ(r.exit_code, 2) << flags << ": " << r.err;
    EXPECT_NE(r.err.find(field), std::string::npos) << flags << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "g.sqlite")) << flags;
  }
  const auto r = run_command(shell_quote(kGridfreeExe.string()) + " run " +
                                 shell_quote((dir / "misspelt.json").string()) + db + " --executor slurm",
                             dir / "err.txt");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/slurm/partiton"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'partition'?"), std::string::npos) << r.err;
}

}  // namespace
