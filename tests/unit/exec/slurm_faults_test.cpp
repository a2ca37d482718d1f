// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm fault classes (exec/slurm_faults.h) on Slurm 22.05's own messages,
// as sbatch and squeue print them.
#include <gtest/gtest.h>

#include "exec/slurm_faults.h"

namespace gridfree {
namespace {

TEST(SlurmFaults, ControllerOutagesAndQueueLimitsAreTransient) {
  // Printed by sbatch with slurmctld stopped (tests/integration/slurm).
  EXPECT_EQ(classify_submit_failure(1,
                                    "sbatch: error: Batch job submission failed: Unable to contact slurm controller "
                                    "(connect failure)\n",
                                    false),
            SubmitFault::kTransient);
  EXPECT_EQ(classify_submit_failure(1, "sbatch: error: Batch job submission failed: Socket timed out on send/recv operation\n", false),
            SubmitFault::kTransient);
  EXPECT_EQ(classify_submit_failure(1,
                                    "sbatch: error: QOSMaxSubmitJobPerUserLimit\nsbatch: error: Batch job submission "
                                    "failed: Job violates accounting/QOS policy (job submit limit, user's size and/or "
                                    "time limits)\n",
                                    false),
            SubmitFault::kTransient);
  EXPECT_EQ(classify_submit_failure(-1, "", false), SubmitFault::kTransient);  // sbatch itself killed
}

TEST(SlurmFaults, RefusalsOfTheJobItselfArePermanent) {
  EXPECT_EQ(classify_submit_failure(1,
                                    "sbatch: error: invalid partition specified: nope\nsbatch: error: Batch job "
                                    "submission failed: Invalid partition name specified\n",
                                    false),
            SubmitFault::kPermanent);
  EXPECT_EQ(classify_submit_failure(1, "sbatch: error: Batch job submission failed: Invalid account or account/partition combination specified\n", false),
            SubmitFault::kPermanent);
  EXPECT_EQ(classify_submit_failure(1, "sbatch: error: Invalid --time specification\n", false), SubmitFault::kPermanent);
  EXPECT_EQ(classify_submit_failure(-1, "sbatch: No such file or directory", true), SubmitFault::kPermanent);
}

TEST(SlurmFaults, TheMessageKeepsSbatchsWordsOnOneLine) {
  EXPECT_EQ(submit_message(1, "sbatch: error: a\n\nsbatch: error: b\n"), "sbatch: error: a | sbatch: error: b");
  EXPECT_EQ(submit_message(7, ""), "sbatch exit 7");
  // The first kSubmitMessageLines lines only.
  EXPECT_EQ(submit_message(1, "1\n2\n3\n4\n5\n6\n7\n"), "1 | 2 | 3 | 4 | 5");
}

TEST(SlurmFaults, ARefusalNamesSbatchsWordsTheCommandAndThatNothingWasSpent) {
  EXPECT_EQ(command_text({"sbatch", "--partition=x", "--job-name=a b", "it's.sh"}),
            "sbatch --partition=x '--job-name=a b' 'it'\\''s.sh'");
  EXPECT_EQ(refused_submission_message(1, "sbatch: error: invalid partition name specified\n",
                                       {"sbatch", "--parsable", "--partition=nope", "/runs/a.sbatch"}),
            "sbatch refused the submission (exit 1): sbatch: error: invalid partition name specified; refused "
            "command: sbatch --parsable --partition=nope /runs/a.sbatch; no job started, no attempt or core-hour "
            "spent");
}

TEST(SlurmFaults, OnlyReasonsNoWaitingCanChangeAreNeverStartable) {
  for (const char* r : {"PartitionTimeLimit", "PartitionNodeLimit", "QOSMaxWallDurationPerJobLimit",
                        "QOSMaxCpuPerJobLimit", "AssocMaxNodePerJobLimit", "InvalidAccount", "BadConstraints"})
    EXPECT_TRUE(never_startable(r)) << r;
  for (const char* r : {"None", "Priority", "Resources", "JobArrayTaskLimit", "QOSMaxJobsPerUserLimit",
                        "AssocGrpCpuLimit", "ReqNodeNotAvail", "PartitionDown", "BeginTime", "Dependency"})
    EXPECT_FALSE(never_startable(r)) << r;
}

}  // namespace
}  // namespace gridfree
