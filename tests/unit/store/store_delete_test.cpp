// SPDX-License-Identifier: GPL-3.0-or-later
// Removing a study (gridfree delete) and replacing a changed one (run
// --replace): shared jobs stay, orphans go with their results and events, finished
// identical jobs are reused; the nominal Δ* and the per-series view v_series.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/input_error.h"
#include "store/store.h"
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
  ASSERT_EQ(r.jobs_removed.size(), 1u);
  EXPECT_EQ(r.jobs_removed.front(), "j2");
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM studies WHERE name = 'a'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs WHERE status = 'queued'"), 1);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM results"), 1);

  // The same definition again is a resume, replace or not.
  EXPECT_FALSE(store.submit(changed, exc, true).replaced);
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
