// SPDX-License-Identifier: GPL-3.0-or-later
// The store's side of adoption after a crash (take_over_stale), the queue
// state shown by `status`, and `retry` of failed jobs.
#include <gtest/gtest.h>

#include <filesystem>

#include "store/store.h"
#include "scratch_dir.h"
#include "store_queries.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

using test_support::scalar;

// One series on `grids` grids.
std::pair<Study, ExpandedStudy> one_series_study(int grids) {
  Study s;
  s.name = "a";
  s.definition = {{"name", "a"}, {"grids", grids}};
  ExpandedStudy ex;
  ex.series.push_back(SeriesKey{"PC1", "superbee", 6.0, "bvk", "diffusion"});
  for (int g = 0; g < grids; ++g) {
    StudyJob j;
    j.grid = static_cast<std::size_t>(g);
    j.cells = {10 + g, 20 + g, 5};
    j.delta_star = 3.0 - 0.5 * g;
    j.doc = {{"grid", g}};
    j.hash = "h" + std::to_string(g);
    ex.jobs.push_back(j);
  }
  return {s, ex};
}

TEST(StoreAdopt, OnlyStaleJobsWithAQueueIdAreTakenOverAttemptsUnchanged) {
  Store store(test_support::fresh_db_path("store_adopt_test", "take"));
  auto [s, ex] = one_series_study(4);
  const auto sub = store.submit(s, ex);
  const std::string dead = "gone:1:1", live = "here:2:2";
  auto j1 = store.claim_next(sub.study_id, dead);  // in Slurm
  auto j2 = store.claim_next(sub.study_id, dead);  // claimed, never submitted
  auto j3 = store.claim_next(sub.study_id, live);  // another live process's
  auto j4 = store.claim_next(sub.study_id, dead);  // a local worker's
  ASSERT_TRUE(j1 && j2 && j3 && j4);
  store.set_job_external_id(j4->job_id, "local:gone:9:9");
  store.set_job_paths(j1->job_id, "/runs/h0/result.json");
  store.set_queue_state(j1->job_id, "slurm:7_0", "PENDING", "Priority");
  store.set_queue_state(j3->job_id, "slurm:7_2", "RUNNING", "");
  const auto alive = [&](const std::string& o) { return o == live; };
  store.set_job_external_id(j3->job_id, "slurm:7_2");
  const auto taken = store.take_over_stale(alive, "me:3:3", "slurm:");
  // j1 (recorded id) and j2 (no id yet: perhaps submitted, not recorded);
  // j3's owner lives; j4 is local (recover_stale_jobs requeues it and kills
  // its orphan).
  ASSERT_EQ(taken.size(), 2u);
  const auto& a1 = taken[0].job.job_id == j1->job_id ? taken[0] : taken[1];
  const auto& a2 = taken[0].job.job_id == j1->job_id ? taken[1] : taken[0];
  EXPECT_EQ(a1.external_id, "slurm:7_0");
  EXPECT_EQ(a1.run_dir, fs::path("/runs/h0"));
  EXPECT_EQ(a1.job.attempts, 1);
  EXPECT_EQ(a2.job.job_id, j2->job_id);
  EXPECT_EQ(a2.external_id, "");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE owner = 'me:3:3' AND status = 'running'"), 2);
  const auto q = store.queue_jobs(sub.study_id);
  ASSERT_EQ(q.size(), 2u);
  const auto& adopted = q[0].job_id == j1->job_id ? q[0] : q[1];
  EXPECT_EQ(adopted.external_id, "slurm:7_0");
  EXPECT_EQ(adopted.state, "PENDING");
  EXPECT_EQ(adopted.reason, "Priority");
}

TEST(StoreAdopt, RetryRequeuesOnlyFailedJobsAndReopensTheStudy) {
  Store store(test_support::fresh_db_path("store_adopt_test", "retry"));
  auto [s, ex] = one_series_study(2);
  const auto sub = store.submit(s, ex);
  auto j1 = store.claim_next(sub.study_id, "me:1:1");
  auto j2 = store.claim_next(sub.study_id, "me:1:1");
  ResultRow ok;
  ok.status = "converged";
  ok.dp_star = 1.0;
  ok.result_json = "{}";
  ResultRow bad;
  bad.reason = "refused by the cluster";
  store.record_result(j1->job_id, "me:1:1", ok);
  store.record_result(j2->job_id, "me:1:1", bad);
  EXPECT_EQ(store.retry_failed(sub.study_id), 1);
  EXPECT_EQ(scalar(store, "SELECT attempts FROM jobs WHERE id = " + std::to_string(j2->job_id)), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);  // the converged result is kept
  EXPECT_EQ(store.active_studies().size(), 1u);
  auto again = store.claim_next(sub.study_id, "me:1:1");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->job_id, j2->job_id);
  EXPECT_EQ(store.retry_failed(sub.study_id), 0);
}

}  // namespace
}  // namespace gridfree
