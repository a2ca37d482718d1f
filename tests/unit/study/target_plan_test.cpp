// SPDX-License-Identifier: GPL-3.0-or-later
// plan --target-rde's model and choice (study/target_plan.h): the log-log
// least squares recovers a and p of an exact power law; fewer than two
// distinct Δ* fall back to the a-priori model; the needed grids run from the
// coarsest to the first predicted at or below the target, at least five (a
// converged verdict needs them);
// a target below every prediction is reported unreachable with all grids.
#include <gtest/gtest.h>

#include <cmath>

#include "study/study_plan.h"
#include "study/target_plan.h"
#include "project_paths.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using test_support::kSourceDir;
using test_support::quickstart_document;
using test_support::study_of;

Study quickstart_study() { return parse_study(kSourceDir / "studies/quickstart.json"); }  // Δ* 2, 1.333, 1, 0.8, 0.667

TEST(TargetPlan, FitRecoversAnExactPowerLaw) {
  std::vector<std::array<double, 2>> pts;
  for (double h : {2.0, 1.5, 1.0, 0.7}) pts.push_back({h, 0.02 * std::pow(h, 1.7)});
  const auto m = fit_rde_model(pts);
  EXPECT_FALSE(m.a_priori);
  EXPECT_EQ(m.points, 4u);
  EXPECT_NEAR(m.p, 1.7, 1e-12);
  EXPECT_NEAR(m.a, 0.02, 1e-14);
  EXPECT_NEAR(m.predict(0.5), 0.02 * std::pow(0.5, 1.7), 1e-14);
}

TEST(TargetPlan, TooLittleDataIsAPriori) {
  EXPECT_TRUE(fit_rde_model({}).a_priori);
  EXPECT_TRUE(fit_rde_model({{1.0, 0.01}, {1.0, 0.02}}).a_priori);  // one Δ*
  EXPECT_TRUE(fit_rde_model({{1.0, 0.01}, {0.5, 0.0}}).a_priori);   // RDE 0 has no logarithm
  const RdeModel m;
  EXPECT_DOUBLE_EQ(m.p, 1.0);
  EXPECT_NEAR(m.predict(0.564), 0.0078, 1e-12);  // the baseline it is taken from
}

TEST(TargetPlan, NeedsGridsDownToTheFirstMeetingTheTargetAndAtLeastFive) {
  auto doc = quickstart_document();
  doc["grids"] = {{"delta_star", {1.6, 2.0, 1.28, 1.02, 0.82, 0.66, 0.52}}};  // any order: sorted coarse to fine
  const Study study = study_of(doc);
  RdeModel m;
  m.a = 0.01;
  m.p = 1;  // RDE = 1 %·Δ*: 2, 1.6, 1.28, 1.02, 0.82, 0.66, 0.52 %
  auto plan = plan_for_target(study, 0.007, m);
  ASSERT_EQ(plan.cases.size(), 1u);
  const auto& c = plan.cases.front();
  EXPECT_EQ(c.series, 2u);
  EXPECT_TRUE(c.reachable);
  EXPECT_EQ(c.grids_needed, 6u);  // Δ* 0.66 is the first ≤ 0.7 %
  EXPECT_DOUBLE_EQ(c.grids[5].delta_star, 0.66);
  EXPECT_TRUE(c.grids[5].needed);
  EXPECT_FALSE(c.grids[6].needed);
  double cpu = 0;
  for (std::size_t k = 0; k < 6; ++k) cpu += c.grids[k].cpu_s;
  EXPECT_DOUBLE_EQ(c.cpu_s_per_series, cpu);
  EXPECT_DOUBLE_EQ(plan.total_cpu_s, 2 * cpu);
  EXPECT_DOUBLE_EQ(c.peak_memory_bytes, c.grids[5].memory_bytes);
  plan = plan_for_target(study, 0.05, m);  // met by the coarsest: still five
  EXPECT_EQ(plan.cases.front().grids_needed, kMinGridsForConverged);
}

TEST(TargetPlan, UnreachableTargetUsesEveryGridAndSaysSo) {
  RdeModel m;
  m.a = 0.01;
  const auto plan = plan_for_target(quickstart_study(), 0.001, m);
  EXPECT_FALSE(plan.cases.front().reachable);
  EXPECT_EQ(plan.cases.front().grids_needed, 5u);
  EXPECT_NE(target_plan_text(plan).find("not reachable"), std::string::npos);
  EXPECT_FALSE(target_plan_json(plan)["cases"][0]["reachable"].get<bool>());
}

// Four grids can never give a converged verdict (n − 3 ≥ 2 needs five): a
// target the predictions meet is still not reachable, and the text says so
// instead of "needs 4 grids".
TEST(TargetPlan, FewerThanFiveGridsAreNeverEnough) {
  auto doc = quickstart_document();
  doc["grids"] = {{"delta_star", {2.0, 1.5, 1.2, 1.0}}};
  RdeModel m;
  m.a = 0.01;
  const auto plan = plan_for_target(study_of(doc), 0.05, m);  // every grid predicts ≤ 2 %
  const auto& c = plan.cases.front();
  EXPECT_FALSE(c.enough_grids);
  EXPECT_FALSE(c.reachable);
  EXPECT_EQ(c.grids_needed, 4u);
  const std::string text = target_plan_text(plan);
  EXPECT_EQ(text.find("needs 4 grids"), std::string::npos) << text;
  EXPECT_NE(text.find("a converged verdict needs 5"), std::string::npos) << text;
  EXPECT_FALSE(target_plan_json(plan)["cases"][0]["enough_grids"].get<bool>());
  ASSERT_EQ(target_plan_warnings(plan).size(), 1u);
  EXPECT_TRUE(target_plan_warnings(plan_for_target(quickstart_study(), 0.05, m)).empty());  // five grids
}

TEST(TargetPlan, CostScaleMultipliesTheCostModel) {
  RdeModel m;
  const auto one = plan_for_target(quickstart_study(), 0.01, m);
  m.cost_scale = 3;
  const auto three = plan_for_target(quickstart_study(), 0.01, m);
  EXPECT_NEAR(three.total_cpu_s, 3 * one.total_cpu_s, 1e-9 * one.total_cpu_s);
}

// Finished similar jobs (the plan's history rule, study/cost_model.h) set a
// grid's cost in place of cost_scale × the a-priori model: one sample at
// ratio 1.7 of the base model makes every grid cost 1.7 × base.
TEST(TargetPlan, HistoryOfSimilarJobsSetsTheCosts) {
  const Study s = quickstart_study();
  RdeModel m;
  m.cost_scale = 3;  // not used where the history applies
  const auto key = design_series(s).front();
  const auto cells = grids_for_case(s, s.cases.front()).front();
  const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
  CostHistory history;
  history[cost_similarity_key(make_job_document(s, key, cells))] = {{n, 1.7 * base_cpu_seconds(n)}};
  const auto plan = plan_for_target(s, 0.01, m, history);
  ASSERT_FALSE(plan.cases.front().grids.empty());
  EXPECT_TRUE(plan.cases.front().costs_from_history);
  for (const auto& g : plan.cases.front().grids) {
    const double base = base_cpu_seconds(static_cast<double>(g.cells[0]) * g.cells[1] * g.cells[2]);
    EXPECT_NEAR(g.cpu_s, 1.7 * base, 1e-9 * base);
  }
  EXPECT_TRUE(target_plan_json(plan)["cases"][0]["costs_from_history"].get<bool>());
  EXPECT_EQ(target_plan_json(plan)["cases"][0]["grids"][0]["cost_source"], "history");
  EXPECT_FALSE(plan_for_target(s, 0.01, m).cases.front().costs_from_history);
}

// The header says where the costs come from: the history where it applied
// to every grid, the a-priori model (and its scale) where it applied to none.
TEST(TargetPlan, HeaderNamesTheCostSourceThatWasUsed) {
  const Study s = quickstart_study();
  RdeModel m;
  m.cost_scale = 3;
  const auto key = design_series(s).front();
  const auto cells = grids_for_case(s, s.cases.front()).front();
  const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
  CostHistory history;
  history[cost_similarity_key(make_job_document(s, key, cells))] = {{n, 1.7 * base_cpu_seconds(n)}};
  const std::string measured = target_plan_text(plan_for_target(s, 0.01, m, history));
  const std::string header = measured.substr(0, measured.find("\ncase "));
  EXPECT_NE(header.find("costs of every grid from finished similar jobs"), std::string::npos) << header;
  EXPECT_EQ(header.find("a-priori cost model"), std::string::npos) << header;
  const std::string modelled = target_plan_text(plan_for_target(s, 0.01, m));
  EXPECT_NE(modelled.find("costs from the a-priori cost model × 3"), std::string::npos) << modelled;
  EXPECT_EQ(modelled.find("similar jobs"), std::string::npos) << modelled;
  EXPECT_EQ(target_plan_json(plan_for_target(s, 0.01, m))["cost_basis"], cost_basis_text(plan_for_target(s, 0.01, m)));
}

}  // namespace
}  // namespace gridfree
