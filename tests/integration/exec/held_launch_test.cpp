// SPDX-License-Identifier: GPL-3.0-or-later
// Held launches of LocalExecutor (exec/local_executor.h): the worker's
// process exists (its identity can be recorded) but does not run until
// release(); if the orchestrator dies before releasing, the worker never
// runs, so no worker can outlive a killed orchestrator unrecorded.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "exec/local_executor.h"
#include "project_paths.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using test_support::kFakeWorker;

JobLaunch held_launch(const fs::path& root) {
  const nlohmann::json doc = {{"case", {{"name", "ok"}, {"domain_dp", {30, 200, 10}}}},
                              {"numerics", {{"grid", {{"cells", {10, 60, 3}}}}}}};
  JobLaunch j;
  j.job_id = 7;
  j.job_hash = "held";
  j.run_dir = prepare_run_dir(root, j.job_hash, doc.dump(2));
  j.hold = true;
  return j;
}

bool process_exists(pid_t pid) { return ::kill(pid, 0) == 0; }

TEST(HeldLaunch, TheWorkerRunsOnlyAfterRelease) {
  const auto root = test_support::fresh_scratch_dir("held_launch", "release");
  LocalExecutor ex(kFakeWorker);
  const JobLaunch job = held_launch(root);
  ex.start(job);
  const std::string id = ex.external_id(job.job_id);
  ASSERT_FALSE(id.empty());
  // Held: no result, however long we wait (the fake worker answers in ms).
  EXPECT_FALSE(ex.wait_any(0.3).has_value());
  EXPECT_FALSE(fs::exists(job.run_dir / "result.json"));
  ex.release(job.job_id);
  const auto e = ex.wait_any(20);
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->how, JobExit::How::kExited);
  EXPECT_EQ(e->code, 0);
  EXPECT_TRUE(fs::exists(job.run_dir / "result.json"));
}

TEST(HeldLaunch, AWorkerWhoseOrchestratorDiesBeforeReleaseNeverRuns) {
  const auto root = test_support::fresh_scratch_dir("held_launch", "orphan");
  const JobLaunch job = held_launch(root);
  int ids[2];
  ASSERT_EQ(::pipe(ids), 0);
  const pid_t orchestrator = ::fork();
  ASSERT_GE(orchestrator, 0);
  if (orchestrator == 0) {  // a stand-in orchestrator: starts, reports the pid, dies unreleased
    ::close(ids[0]);
    auto* ex = new LocalExecutor(kFakeWorker);  // leaked on purpose: no destructor, as under kill -9
    ex->start(job);
    const std::string id = ex->external_id(job.job_id);
    (void)!::write(ids[1], id.data(), id.size());
    ::_exit(0);
  }
  ::close(ids[1]);
  char buf[256] = {};
  const ssize_t n = ::read(ids[0], buf, sizeof buf - 1);
  ::close(ids[0]);
  int status = 0;
  ::waitpid(orchestrator, &status, 0);
  ASSERT_GT(n, 0);
  std::string id(buf, static_cast<std::size_t>(n));  // local:host:pid:start
  ASSERT_EQ(id.rfind("local:", 0), 0u) << id;
  id = id.substr(6);
  const pid_t worker = static_cast<pid_t>(std::stol(id.substr(id.find(':') + 1)));
  // The held child sees the pipe close and exits; it is reparented, so poll.
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = !process_exists(worker);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  EXPECT_TRUE(gone) << "the held worker outlived its orchestrator";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_FALSE(fs::exists(job.run_dir / "result.json")) << "the worker ran without being released";
}

}  // namespace
}  // namespace gridfree
