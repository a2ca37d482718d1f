// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker solve --checkpoint/--resume (docs/INTERFACE.md §2,
// "Checkpoints"): a solve stopped by SIGTERM at about half its outer
// iterations writes a checkpoint and exits 130; resumed, it finishes in the
// remaining iterations with the dp* of an uninterrupted run (computed here).
// A corrupt checkpoint, or one of another job, is ignored with a warning.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "contract_job.h"
#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

// The docs/INTERFACE.md job on 15x100x5 cells (Δ* = 2). Its nested start's
// coarse level writes no progress and no checkpoint: the iterations counted
// and resumed below are the job's own grid's.
nlohmann::json small_bed_job() {
  nlohmann::json job = gridfree::test::contract_job();
  job["numerics"]["grid"] = {{"cells", {15, 100, 5}}};
  job["numerics"]["deposition"] = {{"kind", "diffusion"}, {"fwhm_dp", 6}};
  job["numerics"]["max_iterations"] = 2000;
  return job;
}

using gridfree::test_support::load_json;
using gridfree::test_support::save_json;
using gridfree::test_support::slurp;

std::string worker() { return std::string(GRIDFREE_BIN_DIR) + "/gridfree-worker"; }

gridfree::test_support::CommandRun solve(const fs::path& dir, const std::string& result, const std::string& extra) {
  return gridfree::test_support::run_command(worker() + " solve '" + (dir / "job.json").string() + "' -o '" +
                                                 (dir / result).string() + "' --threads 1 " + extra,
                                             dir / "stderr.txt");
}

// Runs the worker with -v (progress file rewritten every iteration) and
// sends SIGTERM once the progress file reports `stop_at` iterations.
// Returns the exit code (-1 when it ended by a signal).
int solve_and_terminate_at(const fs::path& dir, int stop_at) {
  const std::vector<std::string> args = {worker(), "solve", (dir / "job.json").string(), "-o",
                                         (dir / "result.json").string(), "--threads", "1", "-v",
                                         "--progress", (dir / "progress.json").string(),
                                         "--checkpoint", (dir / "checkpoint.bin").string(),
                                         "--resume", (dir / "checkpoint.bin").string()};
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int log = ::open((dir / "stopped.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(log, 1);
    ::dup2(log, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  bool sent = false;
  for (int i = 0; i < 6000 && !sent; ++i) {  // at most 10 min
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    try {
      if (fs::exists(dir / "progress.json") && load_json(dir / "progress.json")["iteration"].get<int>() >= stop_at) {
        ::kill(pid, SIGTERM);
        sent = true;
      }
    } catch (const std::exception&) {  // read between the worker's writes: try again
    }
    if (!sent) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!sent) ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CheckpointCli, StoppedAtHalfResumesToTheUninterruptedResult) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("checkpoint_cli", "half");
  save_json(dir / "job.json", small_bed_job());
  // Reference: uninterrupted.
  const auto ref_run = solve(dir, "reference.json", "-q");
  ASSERT_EQ(ref_run.exit_code, 0) << ref_run.err;
  const nlohmann::json ref = load_json(dir / "reference.json");
  const int n = ref["iterations"].get<int>();
  const double dp_ref = ref["srq"]["dp_star"].get<double>();
  ASSERT_GE(n, 20) << "too few iterations to stop half-way";

  // Stopped at about half: exit 130, a checkpoint, no result.
  ASSERT_EQ(solve_and_terminate_at(dir, n / 2), 130) << slurp(dir / "stopped.log");
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin"));
  EXPECT_FALSE(fs::exists(dir / "result.json"));
  // The progress file times the outer iterations (what the orchestrator's
  // stop grace is sized by): 0 < latest ≤ longest ≤ the whole elapsed time.
  const nlohmann::json progress = load_json(dir / "progress.json");
  ASSERT_TRUE(progress["iteration_s"].is_number() && progress["longest_iteration_s"].is_number()) << progress;
  EXPECT_GT(progress["iteration_s"].get<double>(), 0.0);
  EXPECT_LE(progress["iteration_s"].get<double>(), progress["longest_iteration_s"].get<double>());
  EXPECT_LE(progress["longest_iteration_s"].get<double>(), progress["elapsed_s"].get<double>());

  // Resumed: continues after the checkpoint's iteration k (n/2 ≤ k < n: the
  // signal arrives during some iteration ≥ n/2, which is finished first).
  const auto resumed = solve(dir, "result.json", "--checkpoint '" + (dir / "checkpoint.bin").string() +
                                                     "' --resume '" + (dir / "checkpoint.bin").string() + "'");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const nlohmann::json res = load_json(dir / "result.json");
  const int k = res["extra"]["resumed_from_iteration"].get<int>();
  EXPECT_GE(k, n / 2);
  EXPECT_LT(k, n);
  // The resumed solve repeats the uninterrupted one's iterations k+1..n: the
  // checkpoint holds everything the next iteration reads (p, u, β, βv̄, the
  // QoI history and the blow-up references), so the same total count.
  EXPECT_EQ(res["iterations"].get<int>(), n);
  EXPECT_LE(res["iterations"].get<int>() - k, n - n / 2);
  // dp* within 1e-6 of the uninterrupted run (the tolerance, far
  // below the steady tolerance 1e-5 relative ≈ 1e-2 absolute here).
  EXPECT_NEAR(res["srq"]["dp_star"].get<double>(), dp_ref, 1e-6);
  RecordProperty("iterations_uninterrupted", n);
  RecordProperty("stopped_after", k);
  std::printf("uninterrupted %d iterations; stopped after %d, resumed for %d; dp* %.10g vs %.10g\n", n, k,
              res["iterations"].get<int>() - k, res["srq"]["dp_star"].get<double>(), dp_ref);
}

// A checkpoint that is corrupt or belongs to another job is never used.
TEST(CheckpointCli, CorruptOrForeignCheckpointIsIgnoredWithAWarning) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("checkpoint_cli", "refused");
  nlohmann::json other = small_bed_job();
  other["numerics"]["max_iterations"] = 1999;  // another job (hash), same grid
  save_json(dir / "job.json", other);
  const int code = solve_and_terminate_at(dir, 10);
  ASSERT_EQ(code, 130) << slurp(dir / "stopped.log");
  ASSERT_TRUE(fs::exists(dir / "checkpoint.bin"));

  save_json(dir / "job.json", small_bed_job());
  const std::string resume = "--resume '" + (dir / "checkpoint.bin").string() + "'";
  const auto foreign = solve(dir, "foreign.json", resume);
  ASSERT_EQ(foreign.exit_code, 0) << foreign.err;
  EXPECT_NE(foreign.err.find("ignoring the checkpoint"), std::string::npos) << foreign.err;
  EXPECT_NE(foreign.err.find("belongs to job"), std::string::npos) << foreign.err;
  EXPECT_FALSE(load_json(dir / "foreign.json")["extra"].contains("resumed_from_iteration"));

  // Flip one byte in the middle (the arrays): the checksum refuses it.
  std::string bytes = slurp(dir / "checkpoint.bin");
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
  std::ofstream(dir / "checkpoint.bin", std::ios::binary | std::ios::trunc) << bytes;
  const auto corrupt = solve(dir, "corrupt.json", resume);
  ASSERT_EQ(corrupt.exit_code, 0) << corrupt.err;
  EXPECT_NE(corrupt.err.find("checksum mismatch"), std::string::npos) << corrupt.err;
  EXPECT_FALSE(load_json(dir / "corrupt.json")["extra"].contains("resumed_from_iteration"));
}

// `gridfree run` deletes a job's checkpoint once its result is stored (fake
// worker mode ckok: leaves checkpoint.bin behind and converges).
TEST(CheckpointCli, RunRemovesCheckpointsOfStoredResults) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("checkpoint_cli", "cleanup");
  auto doc = gridfree::test_support::quickstart_document();
  doc["name"] = "cleanup";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"ckok", pc1}};
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.5}}};
  save_json(dir / "cleanup.json", doc);
  const auto r = gridfree::test_support::gridfree_in(dir, "run cleanup.json -j 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  int results = 0, checkpoints = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "gridfree.sqlite.runs")) {
    results += e.path().filename() == "result.json";
    checkpoints += e.path().filename() == "checkpoint.bin";
  }
  EXPECT_EQ(results, 4);
  EXPECT_EQ(checkpoints, 0);
}

}  // namespace
