// SPDX-License-Identifier: GPL-3.0-or-later
// The two case kinds (study/case_kind.h): which kind a series, a study or a
// job is, and each kind's answers — job labels and queue names, how jobs
// are counted and stored, the adaptive ladder's rungs and their jobs.
#include <gtest/gtest.h>

#include <cmath>

#include "study/case_kind.h"

namespace gridfree {
namespace {

using nlohmann::json;

json bed_job() {
  return json::parse(R"({"schema": "gridfree/job/1",
    "case": {"name": "PC1", "domain_dp": [10, 20, 5]},
    "numerics": {"grid": {"cells": [9, 61, 3]}}})");
}

json external_job() {
  return json::parse(R"({"schema": "gridfree/job/1",
    "case": {"name": "cavity", "external": {
      "template_sha256": "ab", "command": ["run"], "version": "1",
      "levels": {"scheme": "QUICK", "tol": "1e-6"},
      "collect": {"quantities": {"kinetic_energy": {"file": "out.dat", "column": 1},
                                 "ux_probe": {"file": "out.dat", "column": 2}}}}},
    "numerics": {"grid": {"level": 2, "h": 0.125, "cells": 64}}})");
}

TEST(CaseKind, IsChosenFromTheSeriesTheStudyOrTheJob) {
  SeriesKey bed{"PC1", "superbee", 6, "bvk", "diffusion"};
  SeriesKey ext{"cavity", "", 0, "", ""};
  ext.quantity = "kinetic_energy";
  EXPECT_EQ(case_kind(bed).name(), "particle_bed");
  EXPECT_EQ(case_kind(ext).name(), "external");
  EXPECT_EQ(&case_kind(ext), &external_kind());
  EXPECT_EQ(case_kind_of_job(bed_job()).name(), "particle_bed");
  EXPECT_EQ(case_kind_of_job(external_job()).name(), "external");
  EXPECT_EQ(case_kind_of_job(json()).name(), "particle_bed");
  EXPECT_EQ(case_kind(Study{}).name(), "particle_bed");  // no cases yet: gridfree's own
  EXPECT_EQ(case_kind_of_definition(json::parse(R"({"cases": {"PC1": {"bed": "x"}}})")).name(), "particle_bed");
  EXPECT_EQ(case_kind_of_definition(json::parse(R"({"cases": {"c": {"external": {}}}})")).name(), "external");
  EXPECT_EQ(case_kind_of_definition(json()).name(), "particle_bed");
}

// The kind that runs a study and the words its report uses
// (study/case_vocabulary.h) are chosen from the same definition alike,
// including a case that gets its external section through "extends".
TEST(CaseKind, SpeaksTheVocabularyOfTheKindChosenFromTheSameDefinition) {
  for (const char* text : {R"({"cases": {"PC1": {"bed": "x"}}})", R"({"cases": {"c": {"external": {}}}})",
                           R"({"cases": {"base": {"external": {}}, "c": {"extends": "base"}}})", "{}"}) {
    const json definition = json::parse(text);
    EXPECT_EQ(case_kind_of_definition(definition).id(), case_kind_id_of(definition)) << text;
  }
  EXPECT_EQ(particle_bed_kind().id(), CaseKindId::particle_bed);
  EXPECT_EQ(external_kind().id(), CaseKindId::external);
}

TEST(ParticleBedKind, LabelsAJobByItsSeriesAndCells) {
  const CaseKind& k = particle_bed_kind();
  EXPECT_EQ(k.job_label("PC1 superbee fwhm6 bvk", bed_job(), {9, 61, 3}), "PC1 superbee fwhm6 bvk 9x61x3");
  EXPECT_EQ(k.job_label("PC1 superbee fwhm6 bvk alignment", bed_job(), {9, 62, 3}),
            "PC1 superbee fwhm6 bvk alignment 9x62x3");
  // The queue name: the label without its cells, and the job's Δ*.
  EXPECT_EQ(k.job_name("bubble", "PC1 superbee fwhm6 bvk 9x61x3", 3.3, bed_job()),
            "bubble/PC1 superbee fwhm6 bvk d*=3.3");
}

TEST(ParticleBedKind, OneJobPerSeriesGridAndTheBedColumns) {
  const CaseKind& k = particle_bed_kind();
  EXPECT_FALSE(k.job_serves_several_series());
  EXPECT_FALSE(k.jobs_follow_outside_files());
  EXPECT_TRUE(k.has_bed_columns());
  EXPECT_FALSE(k.cores_are_tasks());  // the worker's threads
  EXPECT_FALSE(k.results_recollectable());
}

// The worker's result is stored as it came; its cost is gridfree's model.
TEST(ParticleBedKind, TakesTheResultAsItIsAndHasNoOwnCost) {
  const CaseKind& k = particle_bed_kind();
  std::string result = R"({"status": "converged", "dp_star": 1016.9})";
  std::array<int, 3> cells{};
  k.take_result(bed_job(), {9, 61, 3}, result, cells);
  EXPECT_EQ(result, R"({"status": "converged", "dp_star": 1016.9})");
  EXPECT_EQ(cells, (std::array<int, 3>{}));
  EXPECT_FALSE(k.own_cost(bed_job(), {9, 61, 3}, {{"PC1", DeclaredCost{2.0, 1.0}}}, {}).has_value());
}

// Δ* 2.5 → 1.25 (ratio 2) on a 10 x 20 x 5 domain: cells round(L/Δ*) per
// direction, each rung's job the first job on those cells, its actual Δ*
// the cube root of the cell volume.
TEST(ParticleBedKind, AdaptiveLadderGivesEachRungItsJobAndDeltaStar) {
  AdaptiveGrids a;
  a.coarsest_delta_star = 2.5;
  a.ratio = 2;
  a.finest_delta_star = 1.25;
  const KindLadder l = particle_bed_kind().adaptive_ladder(json::object(), a, SeriesKey{}, bed_job(), {});
  ASSERT_EQ(l.rungs.size(), 2u);
  ASSERT_EQ(l.specs.size(), 2u);
  ASSERT_EQ(l.h.size(), 2u);
  EXPECT_TRUE(l.scale_by_measured);
  EXPECT_EQ(l.rungs[0].cells, (std::array<int, 3>{4, 8, 2}));
  EXPECT_EQ(l.rungs[1].cells, (std::array<int, 3>{8, 16, 4}));
  EXPECT_DOUBLE_EQ(l.h[0], 2.5);
  EXPECT_DOUBLE_EQ(l.h[1], 1.25);
  EXPECT_EQ(l.specs[1]["numerics"]["grid"], json::parse(R"({"cells": [8, 16, 4]})"));
  EXPECT_EQ(l.specs[1]["case"], bed_job()["case"]);
}

TEST(ExternalKind, LabelsAJobByItsCaseLevelsAndH) {
  const CaseKind& k = external_kind();
  // One job serves both quantities: the label names the case, levels and h, no quantity.
  EXPECT_EQ(k.job_label("cavity scheme=QUICK tol=1e-6 kinetic_energy", external_job(), {64, 1, 1}),
            "cavity scheme=QUICK tol=1e-6 h=0.125");
  json no_levels = external_job();
  no_levels["case"]["external"].erase("levels");
  EXPECT_EQ(k.job_label("cavity kinetic_energy", no_levels, {64, 1, 1}), "cavity h=0.125");
}

// Two configurations on one grid get two queue names (the levels are in it).
TEST(ExternalKind, QueueNameNamesTheLevelsQuantitiesAndH) {
  const CaseKind& k = external_kind();
  EXPECT_EQ(k.job_name("heat", "cavity scheme=QUICK tol=1e-6 h=0.125", 0.125, external_job()),
            "heat/cavity scheme=QUICK tol=1e-6 kinetic_energy,ux_probe h=0.125");
  json other = external_job();
  other["case"]["external"]["levels"]["scheme"] = "upwind";
  EXPECT_EQ(k.job_name("heat", "", 0.125, other), "heat/cavity scheme=upwind tol=1e-6 kinetic_energy,ux_probe h=0.125");
  json no_levels = external_job();
  no_levels["case"]["external"].erase("levels");
  EXPECT_EQ(k.job_name("heat", "", 0.125, no_levels), "heat/cavity kinetic_energy,ux_probe h=0.125");
}

TEST(ExternalKind, OneJobServesTheQuantitiesAndFollowsItsTemplate) {
  const CaseKind& k = external_kind();
  EXPECT_TRUE(k.job_serves_several_series());
  EXPECT_TRUE(k.jobs_follow_outside_files());
  EXPECT_FALSE(k.has_bed_columns());
  EXPECT_TRUE(k.cores_are_tasks());  // mpirun -np @@cores@@
  EXPECT_TRUE(k.results_recollectable());  // read by its collect section
}

// The result gets the collect section it was read with and the job's cells
// (the code does not report them); cells it did report stay.
TEST(ExternalKind, TakesTheCollectSectionAndTheJobsCells) {
  const CaseKind& k = external_kind();
  std::string result = R"({"status":"converged","quantities":{"kinetic_energy":0.0672}})";
  std::array<int, 3> cells{};
  k.take_result(external_job(), {64, 1, 1}, result, cells);
  const json doc = json::parse(result);
  EXPECT_EQ(doc["collected_with"], external_job()["case"]["external"]["collect"]);
  EXPECT_EQ(doc["quantities"]["kinetic_energy"], 0.0672);
  EXPECT_EQ(cells, (std::array<int, 3>{64, 1, 1}));
  std::array<int, 3> reported{8, 8, 1};
  std::string not_json = "garbage";
  k.take_result(external_job(), {64, 1, 1}, not_json, reported);
  EXPECT_EQ(not_json, "garbage");
  EXPECT_EQ(reported, (std::array<int, 3>{8, 8, 1}));
}

// Declared figures first (0.5 s and 2 MiB per cell x 64 cells), else the
// case's history, else unknown: never gridfree's solver model.
TEST(ExternalKind, OwnCostFromDeclaredFiguresElseHistoryElseUnknown) {
  const CaseKind& k = external_kind();
  const auto declared = k.own_cost(external_job(), {64, 1, 1}, {{"cavity", DeclaredCost{0.5, 2.0}}}, {});
  ASSERT_TRUE(declared.has_value());
  EXPECT_DOUBLE_EQ(declared->cpu_s, 32);
  EXPECT_DOUBLE_EQ(declared->memory_bytes, 128.0 * 1024 * 1024);
  EXPECT_EQ(declared->basis, "declared 0.5 CPU s per cell");
  EXPECT_EQ(declared->memory_basis, "declared 2 MB per cell");
  const CostHistory history{{cost_similarity_key(external_job()), {{64, 3, 0}}}};
  const auto measured = k.own_cost(external_job(), {64, 1, 1}, {}, history);
  ASSERT_TRUE(measured.has_value());
  EXPECT_DOUBLE_EQ(measured->cpu_s, 3);  // the measured size itself
  const auto unknown = k.own_cost(external_job(), {64, 1, 1}, {}, {});
  ASSERT_TRUE(unknown.has_value());
  EXPECT_TRUE(std::isnan(unknown->cpu_s));
  EXPECT_TRUE(std::isnan(unknown->memory_bytes));
}

// N = 8 → 128 (ratio 2), h = 1 / N, cells = N²: five rungs whose jobs carry
// the rung's variables and grid, costed from the series' two measured sizes
// (cpu = 0.01 s per cell, fitted exactly), never scaled by gridfree's model.
TEST(ExternalKind, AdaptiveLadderRefinesTheGridVariable) {
  const json definition = json::parse(R"({"cases": {"cavity": {"external": {
      "variables": {"h_cell": "1 / N"}, "h": "1 / N", "cells": "N ^ 2"}}}})");
  AdaptiveGrids a;
  a.ratio = 2;
  a.variable = AdaptiveVariable{"N", 8, 128, true};
  SeriesKey key{"cavity", "", 0, "", ""};
  key.quantity = "kinetic_energy";
  const json first = external_job();
  const CostHistory measured{{cost_similarity_key(first), {{64, 0.64, 0}, {256, 2.56, 0}}}};
  const KindLadder l = external_kind().adaptive_ladder(definition, a, key, first, measured);
  ASSERT_EQ(l.rungs.size(), 5u);
  EXPECT_FALSE(l.scale_by_measured);
  EXPECT_DOUBLE_EQ(l.h[0], 0.125);
  EXPECT_DOUBLE_EQ(l.h[2], 1.0 / 32);
  EXPECT_DOUBLE_EQ(l.h[4], 1.0 / 128);
  EXPECT_EQ(l.rungs[2].cells, (std::array<int, 3>{1024, 1, 1}));
  EXPECT_EQ(l.rungs[1].label, "N = 16, 256 cells");
  EXPECT_NEAR(l.rungs[2].model_cpu_s, 10.24, 1e-9);
  EXPECT_EQ(l.specs[2]["numerics"]["grid"], json::parse(R"({"level": 2, "h": 0.03125, "cells": 1024.0})"));
  EXPECT_EQ(l.specs[2]["case"]["external"]["variables"]["N"], 32);
  EXPECT_EQ(l.specs[2]["case"]["external"]["levels"], first["case"]["external"]["levels"]);
}

}  // namespace
}  // namespace gridfree
