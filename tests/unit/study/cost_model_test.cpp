// SPDX-License-Identifier: GPL-3.0-or-later
// The cost model's case-dependent ratio (study/cost_model.h): Re_p against
// hand-computed values, the a-priori rule on the two physics classes, what
// makes two jobs similar, and the history rule on synthetic samples whose
// CPU times are built from known ratios (so the recovered ratio is exact up
// to rounding: tolerance 1e-12 relative).
#include <gtest/gtest.h>

#include <cmath>

#include "study/cost_model.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

nlohmann::json sscp_like_job() {
  return nlohmann::json::parse(R"({
    "case": {"name": "t1", "domain_dp": [70.639, 374.693, 23.342], "particle_diameter_cm": 0.3256,
             "gas": {"density_g_cm3": 0.0012, "viscosity_g_cm_s": 0.00018},
             "boundaries": {"x": "wall", "z": "wall",
                            "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 219.0},
                            "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
             "particles": {"generator": {"kind": "sscp_like", "seed": 1}}},
    "numerics": {"drag": "bvk"}})");
}

nlohmann::json bubble_job() {
  return nlohmann::json::parse(R"({
    "case": {"name": "PC1", "domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
             "gas": {"density_g_cm3": 0.001, "viscosity_g_cm_s": 0.0002},
             "boundaries": {"x": "periodic", "z": "periodic",
                            "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 20.0},
                            "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
             "particles": {"generator": {"kind": "bursting_bubble", "seed": 1}}},
    "numerics": {"drag": "bvk"}})");
}

// cpu_s of a job of n cells whose ratio to the base model is r.
CostSample sample(double n, double r) { return {n, r * base_cpu_seconds(n)}; }

TEST(CostModel, ParticleReynoldsNumberOfBothCases) {
  // 0.0012 · 219 · 0.3256 / 0.00018 = 475.376; 0.001 · 20 · 0.01 / 0.0002 = 1.
  EXPECT_NEAR(particle_reynolds(sscp_like_job()["case"]), 475.376, 1e-3);
  EXPECT_NEAR(particle_reynolds(bubble_job()["case"]), 1.0, 1e-12);
  EXPECT_EQ(particle_reynolds(nlohmann::json::object()), 0.0);  // no inflow, no gas: 0, not NaN
}

TEST(CostModel, APrioriRatioFollowsReynoldsNumberAndNestedStart) {
  const std::array<int, 3> single{10, 60, 4}, nested{47, 250, 16};  // 2 400 and 188 000 cells
  EXPECT_DOUBLE_EQ(apriori_cost_ratio(bubble_job(), single).ratio, 1.0);  // Re_p = 1
  EXPECT_DOUBLE_EQ(apriori_cost_ratio(bubble_job(), nested).ratio, 1.0);
  const CostRatio sscp = apriori_cost_ratio(sscp_like_job(), single);  // Re_p 475.4 ≥ the reference
  EXPECT_DOUBLE_EQ(sscp.ratio, kReferenceSingleGridRatio);
  EXPECT_EQ(sscp.source, CostSource::kAPriori);
  EXPECT_NE(sscp.basis.find("Re_p 475"), std::string::npos) << sscp.basis;
  EXPECT_DOUBLE_EQ(apriori_cost_ratio(sscp_like_job(), nested).ratio, kReferenceNestedRatio);
  auto periodic = sscp_like_job();  // side walls do not enter
  periodic["case"]["boundaries"]["x"] = periodic["case"]["boundaries"]["z"] = "periodic";
  EXPECT_DOUBLE_EQ(apriori_cost_ratio(periodic, nested).ratio, kReferenceNestedRatio);
  auto re20 = sscp_like_job();  // log-linear in Re_p between 1 and the reference
  re20["case"]["boundaries"]["y_low"]["superficial_velocity_cm_s"] = 219.0 * 20 / 475.376;
  const double w = std::log(20.0) / std::log(kReferenceReP);
  EXPECT_NEAR(apriori_cost_ratio(re20, nested).ratio, 1 + (kReferenceNestedRatio - 1) * w, 1e-9);
  auto creeping = sscp_like_job();
  creeping["case"]["boundaries"]["y_low"]["superficial_velocity_cm_s"] = 0.2;  // Re_p 0.43
  EXPECT_DOUBLE_EQ(apriori_cost_ratio(creeping, nested).ratio, 1.0);
}

TEST(CostModel, SimilarJobsShareSetupAndDragNotNameOrParticles) {
  const auto a = sscp_like_job();
  auto b = a;
  b["case"]["name"] = "t2";
  b["case"]["particles"]["generator"]["seed"] = 2;
  EXPECT_EQ(cost_similarity_key(a), cost_similarity_key(b));
  b["numerics"]["drag"] = "gidaspow_blend";
  EXPECT_NE(cost_similarity_key(a), cost_similarity_key(b));
  auto c = a;
  c["case"]["gas"]["viscosity_g_cm_s"] = 0.0002;
  EXPECT_NE(cost_similarity_key(a), cost_similarity_key(c));
  auto d = a;  // a missing drag is the default level
  d["numerics"].erase("drag");
  EXPECT_EQ(cost_similarity_key(a), cost_similarity_key(d));
}

TEST(CostModel, HistoryTakesTheMedianOfTheNearestSizes) {
  const std::vector<CostSample> h = {sample(6000, 1.5), sample(10000, 2.0), sample(10000, 40.0),
                                     sample(200000, 3.0), sample(180000, 3.0)};
  // Within a factor 2 of 8000: 6000 and both 10000 → median 2 (the outlier 40 does not move it).
  CostRatio r = history_cost_ratio(h, 8000);
  EXPECT_EQ(r.source, CostSource::kHistory);
  EXPECT_EQ(r.jobs, 3u);
  EXPECT_NEAR(r.ratio, 2.0, 2e-12);
  r = history_cost_ratio(h, 150000);  // 180 k and 200 k
  EXPECT_EQ(r.jobs, 2u);
  EXPECT_NEAR(r.ratio, 3.0, 3e-12);
  r = history_cost_ratio(h, 1.5e7);  // beyond the measured range: the nearest measured size only
  EXPECT_EQ(r.jobs, 1u);
  EXPECT_NEAR(r.ratio, 3.0, 3e-12);
  r = history_cost_ratio(h, 1000);  // below it: 6000 alone
  EXPECT_EQ(r.jobs, 1u);
  EXPECT_NEAR(r.ratio, 1.5, 2e-12);
  EXPECT_EQ(history_cost_ratio({}, 1000).jobs, 0u);
  EXPECT_EQ(history_cost_ratio({{6000, 0.0}}, 1000).jobs, 0u);  // no measured time: not a sample
}

TEST(CostModel, JobRatioUsesHistoryOfSimilarJobsElseAPriori) {
  const auto job = sscp_like_job();
  CostHistory history;
  history[cost_similarity_key(job)] = {sample(6000, 1.25)};
  const CostRatio r = job_cost_ratio(history, job, {15, 80, 5});
  EXPECT_EQ(r.source, CostSource::kHistory);
  EXPECT_NEAR(r.ratio, 1.25, 2e-12);
  auto gb = job;
  gb["numerics"]["drag"] = "gidaspow_blend";
  const CostRatio a = job_cost_ratio(history, gb, {15, 80, 5});  // 6 000 cells: a nested-start grid
  EXPECT_EQ(a.source, CostSource::kAPriori);
  EXPECT_DOUBLE_EQ(a.ratio, kReferenceNestedRatio);
  EXPECT_DOUBLE_EQ(job_cost_ratio(history, gb, {10, 60, 4}).ratio, kReferenceSingleGridRatio);
}

TEST(CostModel, EstimatedSecondsScaleWithTheRatio) {
  const std::array<int, 3> c{15, 80, 5};
  EXPECT_DOUBLE_EQ(estimated_seconds(c, 2, 3.0), 3.0 * base_cpu_seconds(6000) / 2);
  EXPECT_DOUBLE_EQ(estimated_seconds(c, 1), base_cpu_seconds(6000));
}

}  // namespace
}  // namespace gridfree
