// SPDX-License-Identifier: GPL-3.0-or-later
// Study expansion and job identity: series counts of both designs (factorial
// = product of levels; one-at-a-time = 1 + Σ(levels − 1), cases counted as a
// factor), no duplicate jobs, cells = round(L*/Δ*), and job_hash sensitivity
// (any change in a job changes it; key order and 20 vs 20.0 do not).
#include <gtest/gtest.h>

#include <set>

#include "job/job_hash.h"
#include "study/study.h"
#include "job/memory_estimate.h"
#include "study/study_plan.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using test_support::kSourceDir;
using test_support::quickstart_document;
using test_support::study_of;

nlohmann::json base_study() {
  auto doc = quickstart_document();
  doc["cases"]["PC2"] = doc["cases"]["PC1"];
  doc["cases"]["PC2"]["particles"]["generator"]["seed"] = 2;
  doc["factors"] = {{"convection", {"superbee", "fou", "muscl"}}, {"fwhm_dp", {6, 4}}, {"drag", {"bvk", "hkl"}}};
  doc["grids"] = {{"delta_star", {3.3, 2.5, 2.0}}};
  return doc;
}

TEST(StudyExpand, FactorialIsEveryCombination) {
  auto doc = base_study();
  doc["design"] = "factorial";
  const auto ex = expand(study_of(doc));
  EXPECT_EQ(ex.series.size(), 2u * 3u * 2u * 2u);  // cases × convection × fwhm × drag
  EXPECT_EQ(ex.jobs.size(), ex.series.size() * 3u);
}

TEST(StudyExpand, OneAtATimeIsBaselinePlusEachOtherLevel) {
  const auto ex = expand(study_of(base_study()));
  // 1 + (cases − 1) + (convection − 1) + (fwhm − 1) + (drag − 1) = 1 + 1 + 2 + 1 + 1
  EXPECT_EQ(ex.series.size(), 6u);
  EXPECT_EQ(ex.series.front().label(), "PC1 superbee fwhm6 bvk");
  std::set<SeriesKey> unique(ex.series.begin(), ex.series.end());
  EXPECT_EQ(unique.size(), ex.series.size());
  for (const auto& k : ex.series) {
    int differences = (k.case_name != "PC1") + (k.convection != "superbee") + (k.fwhm_dp != 6) + (k.drag != "bvk");
    EXPECT_LE(differences, 1) << k.label();
  }
}

TEST(StudyExpand, PaperStudyHasTwelveSeriesOnEighteenGrids) {
  const auto study = parse_study(kSourceDir / "studies/bursting_bubble_paper.json");
  const auto ex = expand(study);
  // PC1 + {PC2, PC3, PC3t} + {fou, muscl} + {4, 8, 16} + {gidaspow_blend, wen_yu, hkl}
  EXPECT_EQ(ex.series.size(), 12u);
  EXPECT_EQ(ex.jobs.size(), 12u * 18u);
  std::set<std::string> hashes;
  for (const auto& j : ex.jobs) hashes.insert(j.hash);
  EXPECT_EQ(hashes.size(), ex.jobs.size());  // no duplicates
}

TEST(StudyExpand, CellsAreRoundedFromDeltaStarPerDirection) {
  const auto ex = expand(study_of(base_study()));
  // L* = 30 × 200 × 10: Δ* = 2.5 → 12 × 80 × 4; Δ* = 3.3 → 9.09, 60.6, 3.03 → 9 × 61 × 3.
  EXPECT_EQ(ex.jobs[1].cells, (std::array<int, 3>{12, 80, 4}));
  EXPECT_EQ(ex.jobs[0].cells, (std::array<int, 3>{9, 61, 3}));
  EXPECT_NEAR(ex.jobs[1].delta_star, std::cbrt(30.0 * 200 * 10 / (12 * 80 * 4)), 1e-12);
  const auto& numerics = ex.jobs[1].doc["numerics"];
  EXPECT_EQ(numerics["grid"]["cells"], nlohmann::json({12, 80, 4}));
  EXPECT_EQ(numerics["convection"], "superbee");
  EXPECT_EQ(numerics["deposition"]["fwhm_dp"], 6.0);
  EXPECT_EQ(numerics["tolerances"]["steady"], 1e-5);  // the study's numerics merged in
  EXPECT_EQ(ex.jobs[1].doc["case"]["name"], "PC1");
}

TEST(StudyExpand, ExplicitCellsAreUsedAsGiven) {
  auto doc = base_study();
  doc["grids"] = {{"cells", {{10, 60, 4}, {20, 120, 8}}}};
  const auto ex = expand(study_of(doc));
  EXPECT_EQ(ex.jobs.size(), 6u * 2u);
  EXPECT_EQ(ex.jobs[1].cells, (std::array<int, 3>{20, 120, 8}));
}

TEST(JobHash, AnyChangeInTheJobChangesItsHash) {
  const auto study = study_of(base_study());
  const auto ex = expand(study);
  const auto& doc = ex.jobs[0].doc;
  const std::string h0 = job_hash(doc);
  EXPECT_EQ(h0, ex.jobs[0].hash);
  const std::vector<std::string> pointers = {"/case/particles/generator/seed", "/case/domain_dp/1",
                                             "/numerics/grid/cells/2", "/numerics/tolerances/steady",
                                             "/numerics/deposition/fwhm_dp", "/case/probes/pressure_drop/y1_dp"};
  for (const auto& p : pointers) {
    auto changed = doc;
    const nlohmann::json::json_pointer ptr(p);
    changed[ptr] = changed[ptr].get<double>() * 1.5 + 1;
    EXPECT_NE(job_hash(changed), h0) << p;
  }
  auto renamed = doc;
  renamed["numerics"]["convection"] = "fou";
  EXPECT_NE(job_hash(renamed), h0);
}

TEST(JobHash, KeyOrderAndIntegerVersusDoubleDoNotMatter) {
  const auto a = nlohmann::json::parse(R"({"case": {"u": 20, "name": "x"}, "numerics": {"grid": {"cells": [1, 2, 3]}}})");
  const auto b = nlohmann::json::parse(R"({"numerics": {"grid": {"cells": [1.0, 2.0, 3.0]}}, "case": {"name": "x", "u": 20.0}})");
  EXPECT_EQ(job_hash(a), job_hash(b));
  EXPECT_EQ(canonical_json(a), canonical_json(b));
}

TEST(StudyPlan, MemoryAndTimeFollowTheNamedModel) {
  const auto study = study_of(base_study());
  const auto ex = expand(study);
  const Plan plan = make_plan(study, ex, 2, 2);
  EXPECT_EQ(plan.jobs, ex.jobs.size());
  const std::array<int, 3> c{12, 80, 4};
  EXPECT_DOUBLE_EQ(estimated_memory_bytes(c), kWorkerBytesPerCell * 3840 + kWorkerBaseBytes);
  EXPECT_DOUBLE_EQ(estimated_seconds(c, 1),
                   (kBaseIterations + kIterationsPerCellRoot * std::cbrt(3840.0)) * 3840 * kSecondsPerCellIteration);
  // Grids the worker starts from a coarser solution cost a fixed number of
  // fine-grid iterations' worth.
  const std::array<int, 3> big{60, 400, 20};
  EXPECT_DOUBLE_EQ(estimated_seconds(big, 2), kNestedIterations * 480000 * kSecondsPerCellIteration / 2);
  EXPECT_DOUBLE_EQ(plan.wall_seconds, plan.seconds / 2);
  EXPECT_FALSE(plan_to_table(plan).empty());
  EXPECT_EQ(plan_to_json(plan)["series"].size(), ex.series.size());
}

}  // namespace
}  // namespace gridfree

namespace gridfree {
namespace {

// A transfer preset is a level of the deposition factor: its jobs carry the
// preset (the worker expands and hashes it), its series name shows it.
TEST(StudyExpand, TransferPresetIsADepositionLevel) {
  auto doc = base_study();
  doc["factors"]["deposition"] = {"diffusion", "fm18"};
  doc["design"] = "factorial";
  const auto ex = expand(study_of(doc));
  ASSERT_EQ(ex.series.size(), 2u * 3u * 2u * 2u * 2u);  // cases × convection × fwhm × drag × deposition
  bool seen = false;
  for (const auto& j : ex.jobs) {
    const auto& dep = j.doc["numerics"]["deposition"];
    if (!dep.contains("preset")) continue;
    seen = true;
    EXPECT_EQ(dep["preset"], "fm18");
    EXPECT_EQ(dep.size(), 2u);  // preset and fwhm_dp only: the preset fixes the rest
  }
  EXPECT_TRUE(seen);
  bool labelled = false;
  for (const auto& k : ex.series) labelled = labelled || k.label().find("fm18") != std::string::npos;
  EXPECT_TRUE(labelled);
}

}  // namespace
}  // namespace gridfree
