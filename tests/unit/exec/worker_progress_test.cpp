// SPDX-License-Identifier: GPL-3.0-or-later
// The stop grace derived from the worker's progress file
// (exec/worker_progress.h): base + 1.5 × the longest outer iteration,
// bounded, and the base whenever the iteration time is unknown.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "exec/worker_progress.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

TEST(StopGrace, IsTheBaseWhenTheIterationTimeIsUnknownOrMeaningless) {
  EXPECT_EQ(stop_grace_seconds(30, std::nullopt), 30);
  EXPECT_EQ(stop_grace_seconds(30, 0.0), 30);
  EXPECT_EQ(stop_grace_seconds(30, -4.0), 30);
  EXPECT_EQ(stop_grace_seconds(30, std::numeric_limits<double>::quiet_NaN()), 30);
  EXPECT_EQ(stop_grace_seconds(30, std::numeric_limits<double>::infinity()), 30);
}

TEST(StopGrace, GrowsWithTheLongestIterationUpToTheBound) {
  EXPECT_DOUBLE_EQ(stop_grace_seconds(30, 2.0), 33.0);
  EXPECT_DOUBLE_EQ(stop_grace_seconds(30, 134.0), 231.0);  // the 14.8 M-cell fm18 job (docs/ORCHESTRATOR.md)
  EXPECT_DOUBLE_EQ(stop_grace_seconds(30, 1e5), kMaxStopGraceSeconds);
  EXPECT_DOUBLE_EQ(stop_grace_seconds(5000, 1e5), 5000);  // never below the base
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::trunc) << text; }

TEST(StopGrace, ReadsTheRunFoldersProgressFile) {
  const auto dir = test_support::fresh_scratch_dir("worker_progress_test", "grace");
  EXPECT_EQ(stop_grace_for_run(dir, 30), 30);  // no file yet
  write(progress_file(dir), R"({"iteration": 9, "iteration_s": 3.5, "longest_iteration_s": 10})");
  EXPECT_DOUBLE_EQ(stop_grace_for_run(dir, 30), 45);
  write(progress_file(dir), R"({"iteration": 1, "iteration_s": null, "longest_iteration_s": null})");
  EXPECT_EQ(stop_grace_for_run(dir, 30), 30);
  write(progress_file(dir), R"({"iteration": 4, "elapsed_s": 400})");  // an older worker's file
  EXPECT_EQ(stop_grace_for_run(dir, 30), 30);
  write(progress_file(dir), R"({"longest_iteration_s": "ten"})");
  EXPECT_EQ(stop_grace_for_run(dir, 30), 30);
  write(progress_file(dir), "{trunc");
  EXPECT_FALSE(read_job_progress(progress_file(dir)));
  EXPECT_EQ(stop_grace_for_run(dir, 30), 30);
}

}  // namespace
}  // namespace gridfree
