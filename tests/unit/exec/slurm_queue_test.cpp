// squeue output parsing (exec/slurm_queue.h).
#include <gtest/gtest.h>

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
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q.at("41_0").state, "RUNNING");
  EXPECT_EQ(q.at("41_0").used_s, 7.0);
  EXPECT_EQ(q.at("41_1").reason, "JobArrayTaskLimit");
  EXPECT_EQ(q.at("42").reason, "PartitionTimeLimit");
}

}  // namespace
}  // namespace gridfree
