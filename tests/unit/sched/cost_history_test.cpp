// SPDX-License-Identifier: GPL-3.0-or-later
// The cost model's history rule end to end on a database (sched/cost_history.h,
// study/cost_model.h, make_plan): a store holding finished jobs of two of
// the three instances of studies/sscp_coarse.json, with CPU times built from
// known ratios to the base model (BVK 1.5, Gidaspow blend 2.5) and one job
// that stopped at max_iterations after a long time. The plan of the study
// must give the third instance's series exactly those ratios (it has no
// jobs of its own in the database: the instances share their setup), leave
// the stopped job out, and fall back to the a-priori ratio for a drag law
// and a case the database has never seen.
#include <gtest/gtest.h>

#include <cmath>

#include "sched/cost_history.h"
#include "scratch_dir.h"
#include "store/store.h"
#include "study/study_plan.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using test_support::kSourceDir;
using test_support::study_of;

double cells_of(const std::array<int, 3>& c) { return static_cast<double>(c[0]) * c[1] * c[2]; }

double known_ratio(const std::string& drag) { return drag == "bvk" ? 1.5 : 2.5; }

// Stores results for every job of instances t1 and t2; t3's jobs stay unrun.
void fill_history(Store& store, long long study_id) {
  while (auto job = store.claim_next(study_id, "test:1:1")) {
    const std::string name = job->spec["case"]["name"], drag = job->spec["numerics"]["drag"];
    if (name == "t3") continue;
    ResultRow r;
    r.status = "converged";
    r.dp_star = 1.0;
    r.cells = job->cells;
    r.cpu_s = known_ratio(drag) * base_cpu_seconds(cells_of(job->cells));
    r.result_json = "{}";
    if (name == "t2" && drag == "bvk" && job->cells[0] == 15) {  // the coarsest grid, stopped at max_iterations
      r.status = "not_converged";
      r.cpu_s = 300;
    }
    store.record_result(job->job_id, "test:1:1", r);
  }
}

TEST(CostHistory, PlanUsesFinishedSimilarJobsAndFallsBackToAPriori) {
  const auto dir = test_support::fresh_scratch_dir("cost_history_test", "plan");
  const auto db = dir / "g.sqlite";
  const Study study = parse_study(kSourceDir / "studies/sscp_coarse.json");
  const ExpandedStudy ex = expand(study);
  {
    Store store(db);
    fill_history(store, store.submit(study, ex).study_id);
  }
  const CostHistory history = read_cost_history(db);
  ASSERT_EQ(history.size(), 2u);  // one setup × two drag laws
  std::size_t samples = 0;
  for (const auto& [key, s] : history) samples += s.size();
  EXPECT_EQ(samples, 2u * 2u * 4u - 1u);  // t1, t2 × both drags × 4 grids, without the stopped job

  const Plan plan = make_plan(study, ex, 1, 1, history);
  ASSERT_EQ(plan.rows.size(), ex.series.size());
  for (std::size_t s = 0; s < ex.series.size(); ++s) {
    const PlanRow& row = plan.rows[s];
    const double r = known_ratio(ex.series[s].drag);
    double expected = 0;
    for (const auto& j : ex.jobs)
      if (j.series == s) expected += r * base_cpu_seconds(cells_of(j.cells));
    EXPECT_EQ(row.cost_source, CostSource::kHistory) << row.series;
    EXPECT_NEAR(row.cost_ratio_min, r, 1e-12 * r) << row.series;
    EXPECT_NEAR(row.cost_ratio_max, r, 1e-12 * r) << row.series;
    EXPECT_NEAR(row.seconds, expected, 1e-12 * expected) << row.series;
  }
  const auto json = plan_to_json(plan);
  EXPECT_EQ(json["series"][0]["cost_source"], "history");
  EXPECT_NE(plan_to_table(plan).find("history x 1.5"), std::string::npos) << plan_to_table(plan);

  // A drag law the database has not seen: a-priori (Re_p 475; the grids of
  // 6 000 to 34 506 cells are all nested-start grids).
  auto doc = study.definition;
  doc["factors"]["drag"] = {"hkl"};
  const Study hkl = study_of(doc);
  const Plan a = make_plan(hkl, expand(hkl), 1, 1, history);
  for (const auto& row : a.rows) {
    EXPECT_EQ(row.cost_source, CostSource::kAPriori) << row.series;
    EXPECT_DOUBLE_EQ(row.cost_ratio_min, kReferenceNestedRatio) << row.series;
    EXPECT_DOUBLE_EQ(row.cost_ratio_max, kReferenceNestedRatio) << row.series;
  }
  // The bursting bubble from the same database: a-priori, ratio 1 (the base model).
  const Study bubble = parse_study(kSourceDir / "studies/quickstart.json");
  const Plan b = make_plan(bubble, expand(bubble), 1, 1, history);
  EXPECT_EQ(b.rows.front().cost_source, CostSource::kAPriori);
  EXPECT_EQ(b.rows.front().cost_ratio_max, 1.0);
  EXPECT_EQ(read_cost_history(dir / "missing.sqlite").size(), 0u);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing.sqlite"));
}

}  // namespace
}  // namespace gridfree
