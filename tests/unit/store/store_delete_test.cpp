// SPDX-License-Identifier: GPL-3.0-or-later
// Removing a study (gridfree delete) and replacing a changed one (run
// --replace): delete removes the study's jobs no other study uses with their
// results and events; a replace keeps the jobs no study needs any more
// (reused when asked for again) until gc removes them (store/unneeded_jobs.h);
// the nominal Δ* and the per-series view v_series.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/input_error.h"
#include "store/store.h"
#include "store/unneeded_jobs.h"
#include "scratch_dir.h"
#include "store_queries.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

using test_support::converged;
using test_support::scalar;

// One series on the grids `tags` (a job per tag: equal tags = the same job).
std::pair<Study, ExpandedStudy> tagged_study(const std::string& name, const std::vector<std::string>& tags) {
  Study s;
  s.name = name;
  s.definition = {{"name", name}, {"tags", tags}};
  ExpandedStudy ex;
  ex.series.push_back(SeriesKey{"PC1", "superbee", 6.0, "bvk", "diffusion"});
  for (std::size_t g = 0; g < tags.size(); ++g) {
    StudyJob j;
    j.grid = g;
    j.cells = {10 + static_cast<int>(g), 20, 5};
    j.delta_star = 3.0 - 0.5 * static_cast<double>(g);
    j.delta_star_nominal = 3.0 - 0.5 * static_cast<double>(g) + 0.01;
    j.doc = {{"tag", tags[g]}};
    j.hash = tags[g];
    ex.jobs.push_back(j);
  }
  return {s, ex};
}

void finish_all(Store& store, long long study_id) {
  // Grid g has cells (10 + g, 20, 5) and Δ* 3 − 0.5 g (tagged_study).
  while (auto job = store.claim_next(study_id, "me"))
    store.record_result(job->job_id, "me", converged(1000, 3.0 - 0.5 * (job->cells[0] - 10)));
}

TEST(StoreDelete, RemovesTheStudyAndOrphansButKeepsSharedJobs) {
  Store store(test_support::fresh_db_path("store_delete_test", "delete"));
  auto [a, exa] = tagged_study("a", {"shared", "only-a"});
  auto [b, exb] = tagged_study("b", {"shared", "only-b"});
  const auto sa = store.submit(a, exa);
  store.submit(b, exb);
  finish_all(store, sa.study_id);
  ASSERT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 2);

  const auto removed = store.delete_study("a");
  ASSERT_TRUE(removed);
  ASSERT_EQ(removed->size(), 1u);
  EXPECT_EQ(removed->front(), "only-a");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM studies"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM series"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash IN ('shared', 'only-b')"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash = 'only-a'"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);  // the shared job's result stays
  // the removed job's events go with it; the shared job's stay
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE job_id IS NOT NULL AND job_id NOT IN (SELECT id FROM jobs)"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE kind = 'result'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
  EXPECT_FALSE(store.delete_study("a").has_value());
}

TEST(StoreDelete, RefusedWhileAJobRuns) {
  Store store(test_support::fresh_db_path("store_delete_test", "running"));
  auto [a, exa] = tagged_study("a", {"j1", "j2"});
  const auto sa = store.submit(a, exa);
  ASSERT_TRUE(store.claim_next(sa.study_id, "me"));
  EXPECT_THROW(store.delete_study("a"), InputError);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM studies"), 1);  // rolled back
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 2);
}

TEST(StoreDelete, ChangedDefinitionNeedsReplaceAndReusesFinishedJobs) {
  Store store(test_support::fresh_db_path("store_delete_test", "replace"));
  auto [a, exa] = tagged_study("a", {"j1", "j2"});
  const auto first = store.submit(a, exa);
  finish_all(store, first.study_id);

  auto [changed, exc] = tagged_study("a", {"j1", "j3"});
  try {
    store.submit(changed, exc);
    ADD_FAILURE() << "a changed definition was accepted without replace";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--replace"), std::string::npos) << e.what();
  }
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 2);  // untouched

  const auto r = store.submit(changed, exc, true);
  EXPECT_TRUE(r.replaced);
  EXPECT_TRUE(r.created);
  EXPECT_EQ(r.jobs_reused, 1u);  // j1, done, is not run again
  EXPECT_EQ(r.jobs_new, 1u);     // j3
  ASSERT_EQ(r.jobs_unneeded.size(), 1u);  // j2: kept, with its result
  EXPECT_EQ(r.jobs_unneeded.front(), "j2");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM studies WHERE name = 'a'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'queued'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash = 'j2' AND status = 'done'"), 1);

  // The same definition again is a resume, replace or not.
  EXPECT_FALSE(store.submit(changed, exc, true).replaced);
}

// A change and its revert: the first definition's finished jobs were kept,
// so the revert reuses them all and queues nothing; the changed
// definition's queued job, needed by no study now, is cancelled (kept), and
// queued again when a study asks for it.
TEST(StoreDelete, ARevertedChangeReusesTheKeptJobs) {
  Store store(test_support::fresh_db_path("store_delete_test", "revert"));
  auto [a, exa] = tagged_study("a", {"j1", "j2"});
  finish_all(store, store.submit(a, exa).study_id);
  auto [changed, exc] = tagged_study("a", {"j1", "j3"});
  store.submit(changed, exc, true);
  const auto back = store.submit(a, exa, true);
  EXPECT_EQ(back.jobs_reused, 2u);
  EXPECT_EQ(back.jobs_new, 0u);
  EXPECT_EQ(back.jobs_unneeded, std::vector<std::string>{"j3"});
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'queued'"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash = 'j3' AND status = 'cancelled'"), 1);
  EXPECT_FALSE(store.claim_next(back.study_id, "me")) << "nothing to run again";
  const auto again = store.submit(changed, exc, true);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash = 'j3' AND status = 'queued'"), 1);
  EXPECT_EQ(again.jobs_unneeded, std::vector<std::string>{"j2"});
}

// gc: lists exactly the jobs no study links; removing them takes their
// results and events and leaves every linked job, shared or not. delete
// removes the deleted study's own jobs only, not those another study left.
TEST(StoreDelete, GcRemovesExactlyTheUnneededJobs) {
  Store store(test_support::fresh_db_path("store_delete_test", "gc"));
  auto [a, exa] = tagged_study("a", {"shared", "a1", "a2"});
  auto [b, exb] = tagged_study("b", {"shared", "b1"});
  finish_all(store, store.submit(a, exa).study_id);
  finish_all(store, store.submit(b, exb).study_id);
  auto [a2, exa2] = tagged_study("a", {"shared", "a3"});
  store.submit(a2, exa2, true);  // a1, a2 unneeded
  std::vector<std::string> listed;
  for (const auto& j : unneeded_jobs(store.db())) listed.push_back(j.hash);
  EXPECT_EQ(listed, (std::vector<std::string>{"a1", "a2"}));
  EXPECT_EQ(unneeded_jobs(store.db()).front().status, "done");

  // delete b: its own b1 goes, a's unneeded a1 and a2 stay for gc.
  const auto removed = store.delete_study("b");
  ASSERT_TRUE(removed);
  EXPECT_EQ(*removed, std::vector<std::string>{"b1"});
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash IN ('a1', 'a2')"), 2);

  const auto gone = remove_unneeded_jobs(store);
  ASSERT_EQ(gone.size(), 2u);
  EXPECT_EQ(gone[0].hash, "a1");
  EXPECT_EQ(gone[1].hash, "a2");
  EXPECT_TRUE(unneeded_jobs(store.db()).empty());
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 2);  // shared, a3
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE job_hash IN ('shared', 'a3')"), 2);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);  // shared's; a3 is queued
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE job_id IS NOT NULL AND job_id NOT IN (SELECT id FROM jobs)"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM events WHERE kind = 'gc'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
  EXPECT_FALSE(job_hash_stored(store.db(), "a1"));
  EXPECT_TRUE(job_hash_stored(store.db(), "a3"));
}

TEST(StoreDelete, NominalDeltaStarAndTheSeriesView) {
  Store store(test_support::fresh_db_path("store_delete_test", "view"));
  auto [a, exa] = tagged_study("a", {"j1", "j2"});
  const auto sa = store.submit(a, exa);
  finish_all(store, sa.study_id);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM v_results WHERE delta_star_nominal IS NOT NULL"), 2);
  const auto ready = store.series_ready(sa.study_id);
  ASSERT_EQ(ready.size(), 1u);
  const auto pts = store.series_points(ready[0].id);
  ASSERT_EQ(pts.size(), 2u);
  ExtrapolationRow power{"power", 990.0, 1.0, 1.0, std::nullopt, std::nullopt, 0.1, 0.2, 1.25, true, "ok", "{}"};
  std::vector<UncertaintyRow> u;
  for (const auto& p : pts) u.push_back({p.job_id, p.delta_star, 1000.0, 5.0 + p.delta_star, 0.01});
  store.store_extrapolation(ready[0].id, {power}, u);

  // uncertainties copy the requested Δ* of their grid (actual + 0.01 here).
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM uncertainties WHERE abs(delta_star_nominal - delta_star - 0.01) < 1e-12"), 2);
  auto st = store.db().prepare(
      "SELECT study, method, f0, ng, finest_delta_star, finest_delta_star_nominal, finest_u FROM v_series");
  ASSERT_TRUE(st.step());
  EXPECT_EQ(st.as_text(0), "a");
  EXPECT_EQ(st.as_text(1), "power");
  EXPECT_DOUBLE_EQ(st.as_double(2), 990.0);
  EXPECT_EQ(st.as_int(3), 2);
  const double finest = std::min(pts[0].delta_star, pts[1].delta_star);
  EXPECT_DOUBLE_EQ(st.as_double(4), finest);
  EXPECT_DOUBLE_EQ(st.as_double(5), finest + 0.01);
  EXPECT_DOUBLE_EQ(st.as_double(6), 5.0 + finest);  // U of the finest grid, not of another
  EXPECT_FALSE(st.step());
}

}  // namespace
}  // namespace gridfree
