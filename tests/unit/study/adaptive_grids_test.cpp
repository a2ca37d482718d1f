// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive grids in a study (study/adaptive_grids.h): every field checked
// with its JSON pointer, the ladder Δ*_k = coarsest/ratio^k down to
// finest_delta_star, expand() starting each series with its first four rungs,
// and memory sizes with units.
#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "study/adaptive_rungs.h"
#include "study/study.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using test_support::contains;
using test_support::problem_paths;
using test_support::quickstart_document;
using test_support::study_of;

nlohmann::json adaptive_study() {
  auto doc = quickstart_document();
  doc["grids"] = {{"target_rde", 0.01}, {"coarsest_delta_star", 3.3}, {"ratio", 1.25}, {"finest_delta_star", 0.6}};
  return doc;
}

TEST(AdaptiveGrids, ParsesIntoTheLadderAndStartsWithFourRungs) {
  const Study s = study_of(adaptive_study());
  ASSERT_TRUE(s.adaptive_grids);
  EXPECT_DOUBLE_EQ(s.adaptive_grids->target_rde, 0.01);
  ASSERT_EQ(s.grid_delta_star.size(), 8u);  // 3.3/1.25^7 = 0.692 ≥ 0.6 > 0.554
  EXPECT_NEAR(s.grid_delta_star[7], 3.3 / std::pow(1.25, 7), 1e-12);
  const auto ex = expand(s);
  ASSERT_EQ(ex.series.size(), 2u);
  EXPECT_EQ(ex.jobs.size(), 2u * AdaptiveGrids::kFirstGrids);
  for (const auto& j : ex.jobs) {
    ASSERT_TRUE(j.delta_star_nominal);
    EXPECT_DOUBLE_EQ(*j.delta_star_nominal, s.grid_delta_star[j.grid]);
    EXPECT_LT(j.grid, AdaptiveGrids::kFirstGrids);
  }
}

TEST(AdaptiveGrids, RungsCarryTheCellsOfEachDeltaStar) {
  const Study s = study_of(adaptive_study());
  const auto rungs = adaptive_rungs(s.grid_delta_star, s.cases.front().spec.domain_dp);
  ASSERT_EQ(rungs.size(), s.grid_delta_star.size());
  // (The cost model's time is not monotonic in the cells: above 20 k cells
  // the worker's nested start cuts the iterations, study/study_plan.h.)
  for (std::size_t k = 1; k < rungs.size(); ++k) EXPECT_GT(rungs[k].memory_bytes, rungs[k - 1].memory_bytes);
  EXPECT_EQ(rungs[0].cells, (std::array<int, 3>{9, 61, 3}));  // round(30/3.3), round(200/3.3), round(10/3.3)
}

TEST(AdaptiveGrids, EveryBadFieldIsNamed) {
  auto doc = adaptive_study();
  doc["grids"] = {{"target_rde", 1.5}, {"coarsest_delta_star", -1}, {"ratio", 1.05}, {"max_memory", "lots"},
                  {"max_cpu_s", 0}};
  const auto p = problem_paths(doc);
  EXPECT_TRUE(contains(p, "/grids/target_rde")) << ::testing::PrintToString(p);
  EXPECT_TRUE(contains(p, "/grids/coarsest_delta_star")) << ::testing::PrintToString(p);
  EXPECT_TRUE(contains(p, "/grids/ratio")) << ::testing::PrintToString(p);
  EXPECT_TRUE(contains(p, "/grids/finest_delta_star")) << ::testing::PrintToString(p);  // missing
  EXPECT_TRUE(contains(p, "/grids/max_memory")) << ::testing::PrintToString(p);
  EXPECT_TRUE(contains(p, "/grids/max_cpu_s")) << ::testing::PrintToString(p);
}

TEST(AdaptiveGrids, FinestMustBeBelowCoarsestAndLeaveFiveRungs) {
  auto doc = adaptive_study();
  doc["grids"]["finest_delta_star"] = 4.0;
  EXPECT_TRUE(contains(problem_paths(doc), "/grids/finest_delta_star"));
  doc["grids"]["finest_delta_star"] = 1.36;  // 3.3 … 3.3/1.25^3 = 1.69: four rungs
  EXPECT_TRUE(contains(problem_paths(doc), "/grids/finest_delta_star"));
  doc["grids"]["finest_delta_star"] = 1.35;  // 3.3/1.25^4 = 1.3517: five
  EXPECT_TRUE(problem_paths(doc).empty()) << ::testing::PrintToString(problem_paths(doc));
}

TEST(AdaptiveGrids, AListAndATargetExcludeEachOther) {
  auto doc = adaptive_study();
  doc["grids"]["delta_star"] = {2.0, 1.0};
  EXPECT_FALSE(problem_paths(doc).empty());
}

TEST(AdaptiveGrids, StoredDefinitionGivesTheSameSettings) {
  auto doc = adaptive_study();
  doc["grids"]["max_memory"] = "2 GiB";
  doc["grids"]["max_cpu_s"] = 600;
  const auto a = adaptive_grids_of(doc);
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(*a->max_memory_bytes, 2.0 * 1024 * 1024 * 1024);
  EXPECT_DOUBLE_EQ(*a->max_cpu_s, 600);
  EXPECT_FALSE(adaptive_grids_of(quickstart_document()));
}

TEST(AdaptiveGrids, MemorySizes) {
  EXPECT_DOUBLE_EQ(*parse_memory_field("500 MiB"), 500.0 * 1048576);
  EXPECT_DOUBLE_EQ(*parse_memory_field("2.5GB"), 2.5e9);
  EXPECT_DOUBLE_EQ(*parse_memory_field(4096), 4096);
  EXPECT_FALSE(parse_memory_field("12 parsecs"));
  EXPECT_FALSE(parse_memory_field(-1));
  EXPECT_FALSE(parse_memory_field(true));
}

}  // namespace
}  // namespace gridfree
