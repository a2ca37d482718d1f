// SPDX-License-Identifier: GPL-3.0-or-later
// Executors against tests/fixtures/fake_worker.sh: LocalExecutor's exit
// codes, signals, timeouts (the whole process group dies), launch failures
// and kill_all; SlurmExecutor with fake sbatch/squeue/sacct on PATH.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "exec/local_executor.h"
#include "exec/slurm_executor.h"
#include "exec/worker_progress.h"
#include "project_paths.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using test_support::kFakeWorker;

fs::path temp_dir(const std::string& name) { return test_support::fresh_scratch_dir("exec_test", name); }

JobLaunch launch(const fs::path& root, long long id, const std::string& mode, double timeout = 0) {
  const nlohmann::json doc = {{"case", {{"name", mode}, {"domain_dp", {30, 200, 10}}}},
                              {"numerics", {{"grid", {{"cells", {10, 60, 3}}}}}}};
  JobLaunch j;
  j.job_id = id;
  j.job_hash = "hash" + std::to_string(id);
  j.run_dir = prepare_run_dir(root, j.job_hash, doc.dump(2));
  j.timeout_s = timeout;
  return j;
}

JobExit wait_for(Executor& ex, double limit_s = 20) {
  auto e = ex.wait_any(limit_s);
  if (!e) throw std::runtime_error("no job finished in time");
  return *e;
}

TEST(LocalExecutor, ConvergedJobExitsZeroAndWritesItsResultAndLog) {
  const auto root = temp_dir("ok");
  LocalExecutor ex(kFakeWorker);
  ex.start(launch(root, 1, "ok"));
  EXPECT_EQ(ex.in_flight(), 1u);
  const auto e = wait_for(ex);
  EXPECT_EQ(e.job_id, 1);
  EXPECT_EQ(e.how, JobExit::How::kExited);
  EXPECT_EQ(e.code, 0);
  EXPECT_TRUE(fs::exists(e.run_dir / "result.json"));
  EXPECT_NE(tail_of_file(e.run_dir / "worker.log").find("mode ok"), std::string::npos);
  EXPECT_EQ(ex.in_flight(), 0u);
}

TEST(LocalExecutor, ExitCodesAndSignalsAreReported) {
  const auto root = temp_dir("codes");
  LocalExecutor ex(kFakeWorker);
  ex.start(launch(root, 1, "noconv"));
  ex.start(launch(root, 2, "crash"));
  ex.start(launch(root, 3, "invalid"));
  std::map<long long, JobExit> exits;
  for (int i = 0; i < 3; ++i) {
    auto e = wait_for(ex);
    exits[e.job_id] = e;
  }
  EXPECT_EQ(exits[1].code, 3);
  EXPECT_EQ(exits[2].how, JobExit::How::kSignaled);
  EXPECT_EQ(exits[2].signal, SIGSEGV);
  EXPECT_NE(describe(exits[2]).find("SEGV"), std::string::npos);
  EXPECT_EQ(exits[3].code, 2);
}

TEST(LocalExecutor, TimeoutKillsTheWholeProcessGroup) {
  const auto root = temp_dir("timeout");
  LocalExecutor ex(kFakeWorker);
  ex.start(launch(root, 7, "hang", 0.5));
  const std::string id = ex.external_id(7);
  ASSERT_EQ(id.rfind("local:", 0), 0u);
  const pid_t pgid = static_cast<pid_t>(std::stol(id.substr(id.find(':', 6) + 1)));
  const auto e = wait_for(ex);
  EXPECT_EQ(e.how, JobExit::How::kTimedOut);
  // The fake's `sleep 600` child was in the group: once init has reaped it
  // (it is killed already; reaping is asynchronous) the group is empty.
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = killpg(pgid, 0) == -1;
    if (!gone) usleep(25000);
  }
  EXPECT_TRUE(gone);
}

// One job of the fake in `mode` with a timeout, run until it ends.
// The timeouts below leave the fake's shell 1.5 s to install its SIGTERM
// trap: at 0.3–0.5 s a loaded machine (load 8 on 2 cores) sometimes had not,
// and the fake died of the SIGTERM instead of ignoring or answering it.
JobExit timed_out(const std::string& test, const std::string& mode, double timeout_s, double grace_s) {
  const auto root = temp_dir(test);
  LocalExecutor ex(kFakeWorker, grace_s);
  ex.start(launch(root, 1, mode, timeout_s));
  const auto e = wait_for(ex);
  EXPECT_EQ(e.how, JobExit::How::kTimedOut);
  return e;
}

// A timeout is SIGTERM first: the worker writes its checkpoint and exits.
TEST(LocalExecutor, TimeoutSendsSigtermSoTheWorkerCanCheckpoint) {
  const auto e = timed_out("timeout_term", "checkpoint", 1.5, kStopGraceSeconds);
  EXPECT_EQ(e.code, 130);  // its own exit: the scheduler releases it (sched/outcome.h)
  EXPECT_TRUE(fs::exists(checkpoint_file(e.run_dir)));
  EXPECT_LT(e.wall_s, 5.0);  // well before the 30 s grace: it ended on SIGTERM
}

// A worker that finished as the timeout's SIGTERM reached it exits 0 with its
// result: that is an ordinary exit, and the result is kept, not retried.
// The timeout (1.5 s, as above) must come after the fake's shell has set its
// SIGTERM trap; with 0.5 s a loaded machine sometimes started it too late.
TEST(LocalExecutor, AResultWrittenAsTheTimeoutArrivesIsAnOrdinaryExit) {
  const auto root = temp_dir("timeout_late_result");
  LocalExecutor ex(kFakeWorker, kStopGraceSeconds);
  ex.start(launch(root, 1, "lateok", 1.5));
  const auto e = wait_for(ex);
  EXPECT_EQ(e.how, JobExit::How::kExited);
  EXPECT_EQ(e.code, 0);
  EXPECT_TRUE(fs::exists(e.run_dir / "result.json"));
}

// ... and SIGKILL after the grace period when SIGTERM is ignored.
TEST(LocalExecutor, TimeoutEndsAWorkerIgnoringSigtermAfterTheGrace) {
  const auto e = timed_out("timeout_kill", "stubborn", 1.5, 0.5);
  EXPECT_GE(e.wall_s, 2.0);  // timeout + grace
  EXPECT_EQ(e.code, 0);      // SIGKILLed: no exit code of its own
  EXPECT_FALSE(fs::exists(checkpoint_file(e.run_dir)));
}

// Waits until the fake's shell has installed its SIGTERM trap (a loaded
// machine may take its time starting it).
void wait_for_trap(const fs::path& run_dir) {
  for (int k = 0; k < 400 && !fs::exists(run_dir / ".trap_ready"); ++k) usleep(25000);
  ASSERT_TRUE(fs::exists(run_dir / ".trap_ready"));
}

// Two jobs of the fake, in modes `first` and `second`, stopped by a
// shutdown once both have installed their traps: which left a checkpoint.
std::pair<bool, bool> shutdown_checkpoints(const std::string& test, double grace_s, const std::string& first,
                                           const std::string& second) {
  const auto root = temp_dir(test);
  LocalExecutor ex(kFakeWorker, grace_s);
  ex.start(launch(root, 1, first));
  ex.start(launch(root, 2, second));
  wait_for_trap(run_dir_for(root, "hash1"));
  wait_for_trap(run_dir_for(root, "hash2"));
  EXPECT_EQ(ex.kill_all().size(), 2u);
  EXPECT_EQ(ex.in_flight(), 0u);
  return {fs::exists(checkpoint_file(run_dir_for(root, "hash1"))),
          fs::exists(checkpoint_file(run_dir_for(root, "hash2")))};
}

TEST(LocalExecutor, ShutdownLetsWorkersCheckpoint) {
  EXPECT_EQ(shutdown_checkpoints("killall_term", 5, "checkpoint", "stubborn"), std::make_pair(true, false));
}

// A worker whose outer iterations take longer than the base grace gets
// 1.5 × its longest iteration more (exec/worker_progress.h): the fake needs
// 1 s after SIGTERM; the base grace is 0.5 s, its progress file says 2 s
// (grace 3.5 s), the blind one has no progress file (grace 0.5 s: killed
// in mid-iteration).
TEST(LocalExecutor, TheGraceGrowsWithTheWorkersIterationTime) {
  EXPECT_EQ(shutdown_checkpoints("grace", 0.5, "slowcheckpoint", "slowcheckpointblind"), std::make_pair(true, false));
}

TEST(LocalExecutor, ATimeoutsGraceGrowsWithTheWorkersIterationTime) {
  const auto e = timed_out("grace_timeout", "slowcheckpoint", 2.0, 0.5);
  EXPECT_EQ(e.code, 130);
  EXPECT_TRUE(fs::exists(checkpoint_file(e.run_dir)));
}

// A resumed worker reports no iteration time before its second iteration;
// the progress file of the attempt before counts until then.
TEST(LocalExecutor, AResumedWorkerKeepsTheGraceOfItsEarlierAttempt) {
  const auto root = temp_dir("grace_resumed");
  LocalExecutor ex(kFakeWorker, 0.5);
  auto job = launch(root, 4, "slowcheckpointresumed");
  std::ofstream(progress_file(job.run_dir)) << R"({"iteration": 7, "longest_iteration_s": 2.0})";
  ex.start(job);
  wait_for_trap(job.run_dir);
  EXPECT_EQ(ex.kill_all().size(), 1u);
  EXPECT_TRUE(fs::exists(checkpoint_file(job.run_dir)));
}

TEST(LocalExecutor, MissingWorkerIsALaunchFailure) {
  const auto root = temp_dir("missing");
  LocalExecutor ex(root / "no-such-worker");
  ex.start(launch(root, 1, "ok"));
  const auto e = wait_for(ex);
  EXPECT_EQ(e.how, JobExit::How::kLaunchFailed);
}

TEST(LocalExecutor, KillAllStopsEverythingInFlight) {
  const auto root = temp_dir("killall");
  LocalExecutor ex(kFakeWorker);
  ex.start(launch(root, 1, "hang"));
  ex.start(launch(root, 2, "hang"));
  const auto ids = ex.kill_all();
  EXPECT_EQ(ids.size(), 2u);
  EXPECT_EQ(ex.in_flight(), 0u);
  EXPECT_FALSE(ex.wait_any(0.05).has_value());
}

TEST(ProcessIdentity, OnlyTheExactProcessIsKilled) {
  // A made-up start time never matches a live process: nothing is killed.
  const std::string me = process_identity(getpid());
  const std::string fake = me.substr(0, me.rfind(':')) + ":1";
  EXPECT_FALSE(kill_process_group_if_alive(fake));
}

// Fake Slurm: sbatch runs every task of the array at once and prints an id;
// squeue shows the file `squeue` (nothing when absent: the jobs have left
// the queue); sacct answers from a file. (tests/integration/slurm/ runs the real one.)
fs::path fake_slurm(const fs::path& dir) {
  const auto bin = dir / "bin";
  fs::create_directories(bin);
  auto script = [&](const std::string& name, const std::string& body) {
    std::ofstream(bin / name) << "#!/bin/sh\n" << body;
    fs::permissions(bin / name, fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
  };
  script("sbatch", "[ \"$1\" = --parsable ] || exit 9\n"
                   "[ \"$(cat \"" + (dir / "mode").string() + "\")\" = refuse ] && "
                   "{ echo 'sbatch: error: invalid partition name specified' >&2; exit 1; }\n"
                   "echo \"$@\" >> \"" + (dir / "sbatch_args").string() + "\"\n"
                   "n=$(cat \"" + (dir / "next_id").string() + "\" 2>/dev/null || echo 100)\n"
                   "echo $((n + 1)) > \"" + (dir / "next_id").string() + "\"\n"
                   "last=0; for a; do case $a in --array=0-*) last=${a#--array=0-}; last=${last%%%*} ;; esac; script=$a; done\n"
                   "case \"$(cat \"" + (dir / "mode").string() + "\")\" in run)\n"
                   "  i=0; while [ $i -le $last ]; do SLURM_ARRAY_TASK_ID=$i sh \"$script\" >/dev/null 2>&1; i=$((i + 1)); done ;;\n"
                   "esac\n"
                   "echo \"$n;cluster\"\n");
  script("squeue", "cat \"" + (dir / "squeue").string() + "\" 2>/dev/null\nexit 0\n");
  script("sacct", "cat \"" + (dir / "sacct").string() + "\"\n");
  script("scancel", "echo \"$@\" >> \"" + (dir / "scancelled").string() + "\"\n");
  return bin;
}

// The fake sbatch's calls, one line of arguments each.
std::vector<std::string> sbatch_calls(const fs::path& dir) {
  std::ifstream in(dir / "sbatch_args");
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(SlurmExecutor, SubmitsAnArrayAndReadsTheExitCodes) {
  const auto dir = temp_dir("slurm");
  const auto bin = fake_slurm(dir);
  const std::string old_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);
  std::ofstream(dir / "mode") << "run";
  SlurmSettings settings;
  settings.poll_s = 0.05;
  SlurmExecutor ex(kFakeWorker, dir / "runs", settings, 2);
  auto job = launch(dir / "runs", 1, "noconv");
  auto job2 = launch(dir / "runs", 4, "ok");
  ex.start(job);
  ex.start(job2);
  EXPECT_EQ(ex.external_id(1), "");  // gathered, not yet submitted
  ex.flush();
  EXPECT_EQ(ex.external_id(1), "slurm:100_0");
  EXPECT_EQ(ex.external_id(4), "slurm:100_1");
  std::map<long long, JobExit> exits;
  for (int i = 0; i < 2; ++i) {
    const auto e = wait_for(ex);
    exits[e.job_id] = e;
  }
  EXPECT_EQ(exits[1].how, JobExit::How::kExited);
  EXPECT_EQ(exits[1].code, 3);
  EXPECT_EQ(exits[4].code, 0);
  EXPECT_TRUE(fs::exists(job.run_dir / "result.json"));
  EXPECT_TRUE(fs::exists(job2.run_dir / "result.json"));

  // A job that never wrote its exit code: sacct decides.
  std::ofstream(dir / "mode") << "hold";
  std::ofstream(dir / "sacct") << "CANCELLED|0:9\n";
  ex.start(launch(dir / "runs", 2, "ok"));
  ex.flush();
  const auto lost = wait_for(ex);
  EXPECT_EQ(lost.how, JobExit::How::kSignaled);
  EXPECT_EQ(lost.signal, 9);
  std::ofstream(dir / "sacct") << "TIMEOUT|0:0\n";
  ex.start(launch(dir / "runs", 3, "ok"));
  ex.flush();
  EXPECT_EQ(wait_for(ex).how, JobExit::How::kTimedOut);
  setenv("PATH", old_path.c_str(), 1);
}

// A job resubmitted after a stop whose earlier attempt had long outer
// iterations gets Slurm's SIGTERM earlier: 120 s + 1.5 × 210 s = 435 s,
// rounded up to whole minutes (480 s), at most half the time limit.
TEST(SlurmExecutor, TheStopLeadGrowsWithTheEarlierAttemptsIterationTime) {
  const auto dir = temp_dir("slurm_lead");
  const auto bin = fake_slurm(dir);
  const std::string old_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);
  std::ofstream(dir / "mode") << "hold";
  for (const double limit_minutes : {60.0, 6.0}) {
    fs::remove(dir / "sbatch_args");
    SlurmSettings settings;
    settings.poll_s = 0.05;
    settings.time_minutes = limit_minutes;
    SlurmExecutor ex(kFakeWorker, dir / "runs", settings, 2);
    auto fresh = launch(dir / "runs", 1, "ok");
    auto resumed = launch(dir / "runs", 2, "ok");
    std::ofstream(progress_file(resumed.run_dir)) << R"({"iteration": 40, "longest_iteration_s": 210})";
    ex.start(fresh);
    ex.start(resumed);
    ex.flush();
    const auto args = sbatch_calls(dir);
    ASSERT_EQ(args.size(), 2u);  // two arrays: the leads differ
    EXPECT_NE(args[0].find("--signal=B:TERM@120 "), std::string::npos) << args[0];
    const std::string lead = limit_minutes == 60.0 ? "480" : "180";
    EXPECT_NE(args[1].find("--signal=B:TERM@" + lead + " "), std::string::npos) << args[1];
    ex.kill_all();
  }
  setenv("PATH", old_path.c_str(), 1);
}

// The user's SBATCH_TIMELIMIT / SBATCH_MEM_PER_NODE win over the computed
// defaults: gridfree passes no --time/--mem (sbatch would let its command
// line override the environment), and the stop lead stays within the
// environment's limit (half of 6 min = 180 s). Without them the job gets the
// computed values.
TEST(SlurmExecutor, TheUsersSbatchEnvironmentWinsOverTheComputedLimits) {
  const auto dir = temp_dir("slurm_env");
  const auto bin = fake_slurm(dir);
  const std::string old_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);
  std::ofstream(dir / "mode") << "hold";
  auto submitted = [&](const SbatchEnvironment& env) {
    fs::remove(dir / "sbatch_args");
    SlurmSettings settings;
    settings.poll_s = 0.05;
    settings.environment = env;
    SlurmExecutor ex(kFakeWorker, dir / "runs", settings, 1);
    auto job = launch(dir / "runs", 1, "ok", 3600);
    job.cells = {10, 60, 3};
    std::ofstream(progress_file(job.run_dir)) << R"({"iteration": 40, "longest_iteration_s": 210})";
    ex.start(job);
    ex.flush();
    ex.kill_all();
    std::ifstream in(dir / "sbatch_args");
    std::string line;
    std::getline(in, line);
    return line;
  };
  const std::string computed = submitted({});
  EXPECT_NE(computed.find("--time=61 "), std::string::npos) << computed;  // the 1 h timeout + 1 min
  EXPECT_NE(computed.find("--mem="), std::string::npos) << computed;
  SbatchEnvironment env;
  env.time = EnvSetting{"SBATCH_TIMELIMIT", "6"};
  env.memory = EnvSetting{"SBATCH_MEM_PER_NODE", "500M"};
  const std::string given = submitted(env);
  EXPECT_EQ(given.find("--time"), std::string::npos) << given;
  EXPECT_EQ(given.find("--mem"), std::string::npos) << given;
  EXPECT_NE(given.find("--signal=B:TERM@180 "), std::string::npos) << given;
  setenv("PATH", old_path.c_str(), 1);
}

// sbatch refusing a submission for good (a bad partition) spends no
// attempt: no job comes back as finished, the executor reports the fatal
// error and submits nothing more, and kill_all hands every job back.
TEST(SlurmExecutor, APermanentSubmitFailureIsFatalAndSpendsNoAttempt) {
  const auto dir = temp_dir("slurm_refuse");
  const auto bin = fake_slurm(dir);
  const std::string old_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);
  std::ofstream(dir / "mode") << "refuse";
  SlurmSettings settings;
  settings.poll_s = 0.05;
  SlurmExecutor ex(kFakeWorker, dir / "runs", settings, 1);
  ex.start(launch(dir / "runs", 1, "ok"));
  ex.start(launch(dir / "runs", 2, "ok"));
  ex.flush();
  ASSERT_TRUE(ex.fatal_error());
  EXPECT_NE(ex.fatal_error()->find("invalid partition name specified"), std::string::npos) << *ex.fatal_error();
  EXPECT_FALSE(ex.wait_any(0.2));  // nothing finished, nothing failed
  std::ofstream(dir / "mode") << "hold";
  ex.flush();  // not submitted again
  EXPECT_FALSE(fs::exists(dir / "sbatch_args"));
  auto ids = ex.kill_all();
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<long long>{1, 2}));
  setenv("PATH", old_path.c_str(), 1);
}

// Jobs claimed as others end are gathered while enough of ours wait in the
// queue (2N+8, N = 2 here): one sbatch per tenth of array_size (100 here),
// or after 5 s, not one sbatch per job. With few waiting they go at once.
TEST(SlurmExecutor, RefillsAreGatheredWhileTheQueueHoldsEnoughWaitingTasks) {
  const auto dir = temp_dir("slurm_gather");
  const auto bin = fake_slurm(dir);
  const std::string old_path = std::getenv("PATH");
  setenv("PATH", (bin.string() + ":" + old_path).c_str(), 1);
  std::ofstream(dir / "mode") << "hold";
  auto submissions = [&] { return sbatch_calls(dir).size(); };
  SlurmSettings settings;
  settings.poll_s = 3600;  // one poll, at the first wait
  SlurmExecutor ex(kFakeWorker, dir / "runs", settings, 2);
  long long id = 0;
  for (int i = 0; i < 20; ++i) ex.start(launch(dir / "runs", ++id, "ok"));
  ex.flush();  // nothing of ours in the queue: at once
  EXPECT_EQ(submissions(), 1u);
  // Slurm shows the 20 waiting, on one line (exec/slurm_queue.h).
  std::ofstream(dir / "squeue") << "100_[0-19%2]|PENDING|JobArrayTaskLimit|0:00\n";
  EXPECT_FALSE(ex.wait_any(0.1));
  ex.start(launch(dir / "runs", ++id, "ok"));
  ex.flush();
  EXPECT_EQ(submissions(), 1u);  // gathered
  EXPECT_EQ(ex.external_id(id), "");
  for (int i = 0; i < 99; ++i) ex.start(launch(dir / "runs", ++id, "ok"));
  ex.flush();  // 100 gathered: one array
  EXPECT_EQ(submissions(), 2u);
  EXPECT_EQ(ex.external_id(id), "slurm:101_99");
  ex.start(launch(dir / "runs", ++id, "ok"));
  EXPECT_FALSE(ex.wait_any(4.0));
  EXPECT_EQ(submissions(), 2u);
  EXPECT_FALSE(ex.wait_any(1.5));  // 5 s after it was gathered
  EXPECT_EQ(submissions(), 3u);
  EXPECT_EQ(ex.in_flight(), 121u);
  ex.kill_all();
  setenv("PATH", old_path.c_str(), 1);
}

}  // namespace
}  // namespace gridfree
