// SPDX-License-Identifier: GPL-3.0-or-later
// Study-writing conveniences: cases that extend other cases (RFC 7386 merge,
// chains, cycles and unknown bases refused with the path), factors left out
// (their documented defaults), the baseline's defaults, the grid listing of
// `plan` (requested vs actual Δ*) with its close-neighbour warning, and the
// nominal Δ* carried by each job.
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "study/case_extends.h"
#include "study/grid_listing.h"
#include "study/study.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using nlohmann::json;
using test_support::contains;
using test_support::problem_paths;
using test_support::quickstart_document;
using test_support::study_of;

TEST(CaseExtends, MergesObjectsReplacesValuesAndDeletesNulls) {
  json doc = quickstart_document();
  doc["cases"]["PC1"]["name"] = "first";
  doc["cases"]["PC2"] = {{"extends", "PC1"}, {"particles", {{"generator", {{"seed", 2}}}}}};
  doc["cases"]["W"] = {{"extends", "PC2"}, {"boundaries", {{"x", "wall"}}}, {"probes", nullptr}};
  ProblemList problems;
  const json r = resolve_case_extends(doc, problems);
  EXPECT_TRUE(problems.empty());
  const json& pc2 = r["cases"]["PC2"];
  EXPECT_EQ(pc2["particles"]["generator"]["seed"], 2);
  EXPECT_EQ(pc2["particles"]["generator"]["kind"], "bursting_bubble");  // merged, not replaced
  EXPECT_EQ(pc2["domain_dp"], doc["cases"]["PC1"]["domain_dp"]);
  EXPECT_FALSE(pc2.contains("extends"));
  EXPECT_FALSE(pc2.contains("name"));  // a name is never inherited
  const json& w = r["cases"]["W"];
  EXPECT_EQ(w["boundaries"]["x"], "wall");
  EXPECT_EQ(w["boundaries"]["z"], "periodic");
  EXPECT_EQ(w["particles"]["generator"]["seed"], 2);  // through the chain
  EXPECT_FALSE(w.contains("probes"));                  // null removes

  const Study s = study_of(doc);
  ASSERT_NE(s.find_case("PC2"), nullptr);
  EXPECT_EQ(s.find_case("PC2")->doc["name"], "PC2");
  EXPECT_EQ(s.definition["cases"]["PC2"]["extends"], "PC1");  // stored as written
}

TEST(CaseExtends, ExtendedCasesGiveDistinctJobsOnlyWhereTheyDiffer) {
  json doc = quickstart_document();
  doc["factors"] = {{"convection", {"superbee"}}};
  doc.erase("design");
  doc["cases"]["PC2"] = {{"extends", "PC1"}, {"particles", {{"generator", {{"seed", 2}}}}}};
  json copy = quickstart_document();
  copy["factors"] = doc["factors"];
  copy.erase("design");
  copy["cases"]["PC2"] = copy["cases"]["PC1"];
  copy["cases"]["PC2"]["particles"]["generator"]["seed"] = 2;
  const auto a = expand(study_of(doc));
  const auto b = expand(study_of(copy));
  ASSERT_EQ(a.jobs.size(), b.jobs.size());
  for (std::size_t i = 0; i < a.jobs.size(); ++i) EXPECT_EQ(a.jobs[i].hash, b.jobs[i].hash) << i;
}

TEST(CaseExtends, UnknownBasesCyclesAndNonStringsAreRefusedWithThePath) {
  json doc = quickstart_document();
  doc["cases"]["A"] = {{"extends", "B"}};
  doc["cases"]["B"] = {{"extends", "A"}};
  doc["cases"]["S"] = {{"extends", "S"}};
  doc["cases"]["U"] = {{"extends", "nowhere"}};
  doc["cases"]["N"] = {{"extends", 3}};
  ProblemList problems;
  resolve_case_extends(doc, problems);
  std::vector<std::string> where;
  for (const auto& p : problems.problems()) where.push_back(p.where);
  EXPECT_TRUE(contains(where, "/cases/B/extends") || contains(where, "/cases/A/extends"));
  EXPECT_TRUE(contains(where, "/cases/S/extends"));
  EXPECT_TRUE(contains(where, "/cases/U/extends"));
  EXPECT_TRUE(contains(where, "/cases/N/extends"));
  for (const auto& p : problems.problems()) {
    if (p.where == "/cases/S/extends") {
      EXPECT_NE(p.reason.find("cycle"), std::string::npos) << p.reason;
    }
  }
  EXPECT_TRUE(contains(problem_paths(doc), "/cases/U/extends"));
}

TEST(StudyDefaults, FactorsLeftOutTakeTheirDocumentedDefaults) {
  json doc = quickstart_document();
  doc.erase("factors");
  doc.erase("design");
  const Study s = study_of(doc);
  const auto ex = expand(s);
  ASSERT_EQ(ex.series.size(), 1u);
  EXPECT_EQ(ex.series[0].convection, "superbee");
  EXPECT_EQ(ex.series[0].fwhm_dp, 6.0);
  EXPECT_EQ(ex.series[0].drag, "bvk");
  EXPECT_EQ(ex.series[0].deposition, "diffusion");

  json partial = quickstart_document();
  partial["factors"] = {{"drag", {"bvk", "hkl"}}};
  partial["design"] = {{"one_at_a_time", {{"drag", "bvk"}}}};  // the rest: first case, first levels
  const auto ex2 = expand(study_of(partial));
  ASSERT_EQ(ex2.series.size(), 2u);
  EXPECT_EQ(ex2.series[0].label(), "PC1 superbee fwhm6 bvk");
  EXPECT_EQ(ex2.series[1].drag, "hkl");
}

TEST(GridListing, RequestedAndActualDeltaStarAndCells) {
  json doc = quickstart_document();
  doc["grids"] = {{"delta_star", {3.3, 2.0}}};
  const Study s = study_of(doc);
  const auto rows = grid_listing(s);
  ASSERT_EQ(rows.size(), 2u);
  // L* = 30 x 200 x 10 and Δ* 3.3: cells round(L*/3.3) = 9 x 61 x 3.
  EXPECT_EQ(rows[0].cells, (std::array<int, 3>{9, 61, 3}));
  ASSERT_TRUE(rows[0].requested);
  EXPECT_DOUBLE_EQ(*rows[0].requested, 3.3);
  EXPECT_NEAR(rows[0].actual, std::cbrt(30.0 * 200 * 10 / (9.0 * 61 * 3)), 1e-12);
  EXPECT_EQ(rows[1].cell_count, 15u * 100u * 5u);
  const auto ex = expand(s);
  EXPECT_DOUBLE_EQ(*ex.jobs[0].delta_star_nominal, 3.3);
  EXPECT_NEAR(ex.jobs[0].delta_star, rows[0].actual, 1e-15);

  json cells = quickstart_document();
  cells["grids"] = {{"cells", {{10, 60, 4}}}};
  const auto crows = grid_listing(study_of(cells));
  EXPECT_FALSE(crows[0].requested);
  EXPECT_FALSE(expand(study_of(cells)).jobs[0].delta_star_nominal.has_value());
}

TEST(GridListing, WarnsAboutNeighboursCloserThanTheRatio) {
  json doc = quickstart_document();
  doc["grids"] = {{"delta_star", {2.0, 1.5, 1.9}}};  // 2.0 vs 1.9: actual ratio ≈ 1.05
  const auto rows = grid_listing(study_of(doc));
  const auto w = neighbour_warnings(rows);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("/grids/delta_star/2"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("/grids/delta_star/0"), std::string::npos) << w[0];
  // The ratio is taken on the actual Δ*: with it at 1.0 nothing is flagged.
  EXPECT_TRUE(neighbour_warnings(rows, 1.0).empty());
  doc["grids"] = {{"delta_star", {2.0, 1.5, 1.0}}};
  EXPECT_TRUE(neighbour_warnings(grid_listing(study_of(doc))).empty());
}

}  // namespace
}  // namespace gridfree
