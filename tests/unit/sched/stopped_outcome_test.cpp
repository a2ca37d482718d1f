// SPDX-License-Identifier: GPL-3.0-or-later
// Exit 130 of a worker (sched/outcome.h): stopped with a checkpoint written
// during this attempt → released (the next attempt resumes, no attempt
// spent), also when our own timeout sent the SIGTERM; without one, or killed
// after the grace period → retryable.
#include <gtest/gtest.h>

#include <fstream>

#include "sched/outcome.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

JobExit exit_130(const std::filesystem::path& dir) {
  JobExit e;
  e.how = JobExit::How::kExited;
  e.code = 130;
  e.run_dir = dir;
  e.wall_s = 5;
  return e;
}

TEST(StoppedOutcome, FreshCheckpointReleasesTheJob) {
  const auto dir = test_support::fresh_scratch_dir("stopped_outcome", "fresh");
  std::ofstream(checkpoint_file(dir)) << "x";
  EXPECT_EQ(classify_exit(exit_130(dir)).kind, OutcomeKind::kReleased);
}

TEST(StoppedOutcome, NoCheckpointOrAnOldOneIsRetryable) {
  const auto dir = test_support::fresh_scratch_dir("stopped_outcome", "none");
  EXPECT_EQ(classify_exit(exit_130(dir)).kind, OutcomeKind::kRetryable);
  std::ofstream(checkpoint_file(dir)) << "x";
  std::filesystem::last_write_time(checkpoint_file(dir),
                                   std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  EXPECT_EQ(classify_exit(exit_130(dir)).kind, OutcomeKind::kRetryable);  // from an earlier attempt
}

TEST(StoppedOutcome, OurTimeoutAnsweredWithACheckpointReleasesTheJob) {
  const auto dir = test_support::fresh_scratch_dir("stopped_outcome", "timeout");
  std::ofstream(checkpoint_file(dir)) << "x";
  JobExit e = exit_130(dir);
  e.how = JobExit::How::kTimedOut;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kReleased);
  e.code = 0;  // SIGKILLed after the grace period: no exit code of its own
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);
}

TEST(StoppedOutcome, OurTimeoutWithoutAFreshCheckpointIsRetryable) {
  const auto dir = test_support::fresh_scratch_dir("stopped_outcome", "timeout_old");
  JobExit e = exit_130(dir);
  e.how = JobExit::How::kTimedOut;
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);  // none
  std::ofstream(checkpoint_file(dir)) << "x";
  std::filesystem::last_write_time(checkpoint_file(dir),
                                   std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
  EXPECT_EQ(classify_exit(e).kind, OutcomeKind::kRetryable);  // from an earlier attempt
}

}  // namespace
}  // namespace gridfree
