// SPDX-License-Identifier: GPL-3.0-or-later
// How a Slurm task that left the queue ended (exec/slurm_exit.h): sacct's
// words, the worker's result file, the exit_code file.
#include <gtest/gtest.h>

#include <fstream>

#include "exec/slurm_exit.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

TEST(SlurmExit, SacctStatesMapToExits) {
  const JobExit base{7, JobExit::How::kLost, 0, 0, "", "/run", 1.5};
  auto e = exit_from_sacct("COMPLETED|0:0", base);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->how, JobExit::How::kExited);
  EXPECT_EQ(e->code, 0);
  EXPECT_EQ(e->job_id, 7);
  e = exit_from_sacct("FAILED|3:0", base);
  EXPECT_EQ(e->code, 3);
  e = exit_from_sacct("CANCELLED by 0|0:9", base);
  EXPECT_EQ(e->how, JobExit::How::kSignaled);
  EXPECT_EQ(e->signal, 9);
  EXPECT_EQ(exit_from_sacct("TIMEOUT|0:0", base)->how, JobExit::How::kTimedOut);
  EXPECT_EQ(exit_from_sacct("OUT_OF_MEMORY|0:125", base)->how, JobExit::How::kLost);
  EXPECT_EQ(exit_from_sacct("NODE_FAIL|0:0", base)->how, JobExit::How::kLost);
  EXPECT_FALSE(exit_from_sacct("", base));
  EXPECT_FALSE(exit_from_sacct("sacct: error: Slurm accounting storage is disabled", base));
}

TEST(SlurmExit, TheResultFileAndTheExitCodeFileDecideWithoutAccounting) {
  const auto dir = test_support::fresh_scratch_dir("slurm_exit", "files");
  EXPECT_FALSE(exit_code_from_result(dir / "result.json"));
  std::ofstream(dir / "result.json") << R"({"status": "not_converged", "reason": "converged? no"})";
  EXPECT_EQ(exit_code_from_result(dir / "result.json"), 3);
  std::ofstream(dir / "result.json") << R"({"status": "converged"})";
  EXPECT_EQ(exit_code_from_result(dir / "result.json"), 0);
  std::ofstream(dir / "result.json") << "{not json";
  EXPECT_FALSE(exit_code_from_result(dir / "result.json"));
  EXPECT_FALSE(read_exit_code(dir));
  std::ofstream(dir / "exit_code") << "3\n";
  EXPECT_EQ(read_exit_code(dir), 3);
}

}  // namespace
}  // namespace gridfree
