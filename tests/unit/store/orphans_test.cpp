// SPDX-License-Identifier: GPL-3.0-or-later
// Running jobs by whether their claimant lives (store/orphans.h): the
// read-only view `status` uses, with the test a starting run/daemon uses.
#include <gtest/gtest.h>

#include "scratch_dir.h"
#include "store/orphans.h"
#include "store/owner.h"
#include "store/store.h"

namespace gridfree {
namespace orphans_test {

TEST(Orphans, RunningJobsOfAGoneOwnerAreOrphanedOthersLive) {
  Store store(test_support::fresh_db_path("orphans_test", "orphans"));
  Study s;
  s.name = "a";
  s.definition = {{"name", "a"}};
  ExpandedStudy ex;
  ex.series.push_back(SeriesKey{"PC1", "superbee", 6.0, "bvk", "diffusion"});
  for (int g = 0; g < 3; ++g) {
    StudyJob j;
    j.grid = static_cast<std::size_t>(g);
    j.cells = {10 + g, 20 + g, 5};
    j.delta_star = 3.0 - 0.5 * g;
    j.doc = {{"grid", g}};
    j.hash = "orphans-" + std::to_string(g);
    ex.jobs.push_back(j);
  }
  const auto sub = store.submit(s, ex);
  const std::string me = this_process_owner();
  const std::string gone = me.substr(0, me.find(':')) + ":1:999999999999";  // pid 1 with another start time
  const auto orphan = store.claim_next(sub.study_id, gone);
  const auto live = store.claim_next(sub.study_id, me);
  ASSERT_TRUE(orphan && live);
  const auto r = running_jobs_by_study(store);
  ASSERT_EQ(r.size(), 1u);
  const RunningJobs& jobs = r.at(sub.study_id);
  EXPECT_EQ(jobs.orphaned, (std::set<long long>{orphan->job_id}));
  EXPECT_EQ(jobs.live, (std::set<long long>{live->job_id}));
  EXPECT_TRUE(running_jobs_by_study(store, sub.study_id + 1).empty());
  EXPECT_EQ(store.statuses(sub.study_id).front().running, 2);  // read-only: nothing requeued
}

}  // namespace orphans_test
}  // namespace gridfree
