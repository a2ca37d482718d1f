// SPDX-License-Identifier: GPL-3.0-or-later
// A study with the alignment check in the store: variant jobs are queued
// and claimed like any job but stay out of the series' points and
// readiness; v_alignment and alignment_values give the spread of dp* over a
// grid and its variants, checked against the spread computed here from the
// values the test itself recorded. A study without the option has none.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "store/store.h"
#include "store/store_alignment.h"
#include "scratch_dir.h"
#include "quickstart_study.h"
#include "store_queries.h"
#include "study_documents.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::quickstart_document;
using test_support::scalar;
using test_support::study_of;

json study_doc(bool with_alignment) {
  json doc = quickstart_document();
  doc.erase("design");
  doc["factors"] = {{"convection", {"superbee", "fou"}}};
  doc["grids"] = {{"delta_star", {2.0, 1.333, 1.0, 0.8}}};
  if (with_alignment) doc["alignment"] = {{"delta_star", {2.0, 1.0}}, {"ny_offsets", {1, 2}}, {"nx_offsets", {0, 1}}};
  return doc;
}

// A made-up dp* that depends on every cell count (so variants differ).
double fake_dp(const std::array<int, 3>& c) { return 1000.0 + 0.37 * c[1] - 0.11 * c[0] + 0.013 * ((c[0] * c[1]) % 7); }

TEST(StoreAlignment, VariantsRunLikeJobsAndTheViewGivesTheirSpread) {
  const Study s = study_of(study_doc(true));
  const ExpandedStudy ex = expand(s);
  ASSERT_EQ(ex.alignment.size(), 2u * 2u * 4u);
  Store store(test_support::fresh_db_path("store_alignment_test", "with"));
  const auto sub = store.submit(s, ex);
  EXPECT_EQ(sub.jobs_total, ex.jobs.size() + ex.alignment.size());
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), static_cast<long long>(ex.jobs.size() + ex.alignment.size()));
  // Run every series job first: the series are then ready although variants wait.
  std::map<std::string, std::array<int, 3>> cells_of;
  for (const auto& j : ex.jobs) cells_of[j.hash] = j.cells;
  for (const auto& a : ex.alignment) cells_of[a.hash] = a.cells;
  int claimed = 0;
  while (auto job = store.claim_next(sub.study_id, "me")) {
    ResultRow r;
    r.status = "converged";
    r.dp_star = fake_dp(job->cells);
    r.cells = job->cells;
    r.result_json = "{}";
    ASSERT_TRUE(store.record_result(job->job_id, "me", r));
    ++claimed;
  }
  EXPECT_EQ(claimed, static_cast<int>(ex.jobs.size() + ex.alignment.size()));
  const auto series = store.series_of_study(sub.study_id);
  ASSERT_EQ(series.size(), 2u);
  EXPECT_EQ(store.series_points(series[0].id).size(), 4u);  // the four grids, no variants
  EXPECT_EQ(store.series_ready(sub.study_id).size(), 2u);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM v_results"), 8);  // 2 series × 4 grids

  // Expected spread per (series, grid): the grid and its variants, from the expansion.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> values;
  for (const auto& j : ex.jobs)
    if (j.grid == 0 || j.grid == 2) values[{j.series, j.grid}].push_back(fake_dp(j.cells));
  for (const auto& a : ex.alignment) values[{a.series, a.grid}].push_back(fake_dp(a.cells));
  const auto rows = alignment_rows(store.db(), sub.study_id);
  const auto lists = alignment_values(store.db(), sub.study_id);
  ASSERT_EQ(rows.size(), 4u);
  ASSERT_EQ(lists.size(), 4u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t si = rows[i].series_id == series[0].id ? 0 : 1;
    const auto& v = values.at({si, static_cast<std::size_t>(rows[i].grid_index)});
    const double lo = *std::min_element(v.begin(), v.end()), hi = *std::max_element(v.begin(), v.end());
    double mean = 0;
    for (double x : v) mean += x / static_cast<double>(v.size());
    EXPECT_EQ(rows[i].variants, 5);
    EXPECT_EQ(rows[i].converged, 5);
    ASSERT_TRUE(rows[i].spread.has_value());
    EXPECT_NEAR(*rows[i].spread, (hi - lo) / mean, 1e-12);  // round-off of a mean of five ~1e3 values
    ASSERT_EQ(lists[i].dp_star.size(), 5u);
    EXPECT_DOUBLE_EQ(*lists[i].dp_star.front(), v.front());  // the grid's own job first
  }
}

TEST(StoreAlignment, AMissingVariantLeavesTheSpreadEmpty) {
  const Study s = study_of(study_doc(true));
  Store store(test_support::fresh_db_path("store_alignment_test", "missing"));
  const auto sub = store.submit(s, expand(s));
  auto job = store.claim_next(sub.study_id, "me");
  ASSERT_TRUE(job);
  ResultRow r;
  r.status = "converged";
  r.dp_star = 1000;
  ASSERT_TRUE(store.record_result(job->job_id, "me", r));
  for (const auto& row : alignment_rows(store.db(), sub.study_id)) EXPECT_FALSE(row.spread.has_value());
}

TEST(StoreAlignment, DeletingTheStudyRemovesItsVariants) {
  const Study s = study_of(study_doc(true));
  const ExpandedStudy ex = expand(s);
  Store store(test_support::fresh_db_path("store_alignment_test", "delete"));
  store.submit(s, ex);
  const auto removed = store.delete_study(s.name);
  ASSERT_TRUE(removed.has_value());
  EXPECT_EQ(removed->size(), ex.jobs.size() + ex.alignment.size());
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM jobs"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM alignment_jobs"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM pragma_foreign_key_check"), 0);
}

TEST(StoreAlignment, AStudyWithoutTheOptionHasNoVariants) {
  const Study s = study_of(study_doc(false));
  const ExpandedStudy ex = expand(s);
  Store store(test_support::fresh_db_path("store_alignment_test", "without"));
  const auto sub = store.submit(s, ex);
  EXPECT_EQ(sub.jobs_total, ex.jobs.size());
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM alignment_jobs"), 0);
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM study_jobs WHERE alignment_only = 1"), 0);
  EXPECT_TRUE(alignment_values(store.db(), sub.study_id).empty());
  // The series' transfer columns are filled on submit.
  EXPECT_EQ(scalar(store, "SELECT COUNT(*) FROM series WHERE pre_deposition = 'trilinear' AND integration = 'exact'"), 2);
}

}  // namespace
}  // namespace gridfree
