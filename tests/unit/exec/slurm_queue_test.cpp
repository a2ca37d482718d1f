// SPDX-License-Identifier: GPL-3.0-or-later
// squeue output parsing (exec/slurm_queue.h).
#include <gtest/gtest.h>

#include <algorithm>

#include "exec/slurm_queue.h"

namespace gridfree {
namespace {

TEST(SlurmQueue, DurationsInSlurmsFormats) {
  EXPECT_EQ(parse_slurm_duration("0:00"), 0.0);
  EXPECT_EQ(parse_slurm_duration("1:02"), 62.0);
  EXPECT_EQ(parse_slurm_duration("1:02:03"), 3723.0);
  EXPECT_EQ(parse_slurm_duration("2-01:00:00"), 2 * 86400.0 + 3600.0);
  EXPECT_FALSE(parse_slurm_duration("INVALID"));
  EXPECT_FALSE(parse_slurm_duration("UNLIMITED"));
  EXPECT_FALSE(parse_slurm_duration(""));
  EXPECT_FALSE(parse_slurm_duration("1:2:3:4"));
}

TEST(SlurmQueue, OneEntryPerJobOrArrayTask) {
  const auto q = parse_squeue(
      "41_0|RUNNING|None|0:07\n41_1|PENDING|JobArrayTaskLimit|0:00\n42|PENDING|PartitionTimeLimit|0:00\nbroken line\n");
  EXPECT_EQ(q.lines(), 3u);
  ASSERT_NE(q.find("41_0"), nullptr);
  EXPECT_EQ(q.find("41_0")->state, "RUNNING");
  EXPECT_EQ(q.find("41_0")->used_s, 7.0);
  EXPECT_EQ(q.find("41_1")->reason, "JobArrayTaskLimit");
  EXPECT_EQ(q.find("42")->reason, "PartitionTimeLimit");
  EXPECT_EQ(q.find("41_2"), nullptr);
  EXPECT_EQ(q.find("43"), nullptr);
}

// Without -r, squeue (Slurm 22.05) lists an array's waiting tasks on one
// line: "<id>_[<indices>%<throttle>]", indices as ranges and single ones.
TEST(SlurmQueue, AnArraysWaitingTasksOnOneLine) {
  const auto q = parse_squeue(
      "1_[3-9,11,13-30%3]|PENDING|JobArrayTaskLimit|0:00\n"
      "6_[0]|PENDING|JobHeldUser|0:00\n"
      "1_0|RUNNING|None|0:05\n"
      "1_12|RUNNING|None|0:01\n"
      "7_[2-x]|PENDING|Priority|0:00\n"
      "8_[5|PENDING|Priority|0:00\n");
  EXPECT_EQ(q.lines(), 4u);  // the two malformed combined lines are skipped
  for (const char* id : {"1_3", "1_9", "1_11", "1_13", "1_30"}) {
    ASSERT_NE(q.find(id), nullptr) << id;
    EXPECT_EQ(q.find(id)->reason, "JobArrayTaskLimit") << id;
  }
  for (const char* id : {"1_10", "1_31", "1_1", "1_", "1_3x", "7_2", "8_5", "2_3"}) EXPECT_EQ(q.find(id), nullptr) << id;
  EXPECT_EQ(q.find("1_12")->state, "RUNNING");
  EXPECT_EQ(q.find("1_0")->used_s, 5.0);
  ASSERT_NE(q.find("6_0"), nullptr);
  EXPECT_EQ(q.find("6_0")->reason, "JobHeldUser");
}

TEST(SlurmQueue, TheQueryCombinesWaitingArrayTasks) {
  const auto c = squeue_command();
  EXPECT_EQ(std::find(c.begin(), c.end(), "-r"), c.end());
  EXPECT_EQ(c.back(), "%i|%T|%r|%M");
}

}  // namespace
}  // namespace gridfree
