// SPDX-License-Identifier: GPL-3.0-or-later
// Factors, designs and ensembles of an external study
// (study/external_factors.h): the series key holds the study's own factor
// levels, one job per (case × levels × grid) shared by the quantities, the
// level's text in the job document (so in its hash), and problems at
// /factors/<name>. A study without factors keeps the job hashes it had.
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "project_paths.h"
#include "scratch_dir.h"
#include "study/study.h"

namespace gridfree {
namespace external_factors_test {

using nlohmann::json;

// A copy of the poly test solver's template whose input also takes a
// scheme and a relaxation factor.
std::filesystem::path factor_study_dir(const std::string& name) {
  const auto dir = test_support::fresh_scratch_dir("external_factors", name);
  std::filesystem::copy(test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
                        std::filesystem::copy_options::recursive);
  std::ofstream(dir / "poly/input.txt", std::ios::app) << "scheme @@scheme@@\nrelax @@relax@@\n";
  return dir;
}

json poly_study() {
  return json::parse(R"({"schema": "gridfree/study/1", "name": "poly",
    "cases": {"poly": {"external": {
      "template": "poly", "render": ["input.txt"],
      "variables": {"h_cell": "1 / N"}, "h": "1 / N", "cells": "N ^ 2",
      "command": ["sh", "solve.sh"], "version": "poly 1",
      "collect": {"quantities": {
        "f": {"units": "1", "description": "the test function", "file": "out.dat", "column": 1},
        "h_echo": {"units": "m", "file": "out.dat", "column": 0}}}}}},
    "grids": {"variables": {"N": [4, 6, 8, 12]}}})");
}

json factor_study() {
  json doc = poly_study();
  doc["factors"] = json::parse(R"J({"scheme": ["QUICK", "linearUpwind grad(U)"], "relax": [0.5, 1]})J");
  return doc;
}

std::vector<Problem> problems_of(const json& doc, const std::filesystem::path& dir) {
  try {
    parse_study_document(doc, dir);
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

bool has_problem(const std::vector<Problem>& problems, const std::string& where, const std::string& part) {
  for (const auto& p : problems)
    if (p.where == where && p.reason.find(part) != std::string::npos) return true;
  return false;
}

std::string all_problems(const std::vector<Problem>& problems) {
  std::string out;
  for (const auto& p : problems) out += p.where + ": " + p.reason + "\n";
  return out;
}

// Job hashes of the poly study on main before factors existed (commit
// 05ebd34, `gridfree submit` of this document with the fixture template):
// a study without factors must keep them (docs/EXTERNAL.md "Factors").
TEST(ExternalFactors, StudyWithoutFactorsKeepsItsJobHashes) {
  const auto dir = test_support::fresh_scratch_dir("external_factors", "unchanged");
  std::filesystem::copy(test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
                        std::filesystem::copy_options::recursive);
  const ExpandedStudy ex = expand(parse_study_document(poly_study(), dir));
  ASSERT_EQ(ex.jobs.size(), 8u);
  const std::vector<std::string> main_hashes = {
      "afdfa4e6d7be73f6bc337bd13066f331bed21271ea4e14afe6ccf1e205203f2b",
      "f6e82bee38fc6d0454be0e21637a6fae6139b08b90ca8e03df23e673ceb56a0b",
      "0c06ccb577efb201539d0baab7c800fa033bb624fb39f2b346a7fabde2e1719a",
      "a90de9eabd5892de34e1d484f26aabc4bfaba8223b856dc4101a2913075ef4bb"};
  for (std::size_t g = 0; g < 4; ++g) {
    EXPECT_EQ(ex.jobs[g].hash, main_hashes[g]) << "grid " << g;
    EXPECT_FALSE(ex.jobs[g].doc["case"]["external"].contains("levels"));
  }
}

TEST(ExternalFactors, FactorialIsEveryCaseTimesEveryLevelCombination) {
  const auto dir = factor_study_dir("factorial");
  const Study s = parse_study_document(factor_study(), dir);
  const ExpandedStudy ex = expand(s);
  // 1 case × 2 × 2 levels × 2 quantities; factors in name order (relax, scheme).
  ASSERT_EQ(ex.series.size(), 8u);
  EXPECT_EQ(ex.series[0].label(), "poly relax=0.5 scheme=QUICK f");
  EXPECT_EQ(ex.series[1].label(), "poly relax=0.5 scheme=QUICK h_echo");
  EXPECT_EQ(ex.series[2].label(), "poly relax=0.5 scheme=linearUpwind grad(U) f");
  EXPECT_EQ(ex.series[7].label(), "poly relax=1 scheme=linearUpwind grad(U) h_echo");
  EXPECT_EQ(s.design_description(), "factorial");
  // One job per (configuration × grid), listed in each quantity's series.
  EXPECT_EQ(distinct_job_count(ex), 16u);
  ASSERT_EQ(ex.jobs.size(), 32u);
  std::set<std::string> hashes;
  for (const auto& j : ex.jobs) {
    const SeriesKey& k = ex.series[j.series];
    const json& levels = j.doc["case"]["external"]["levels"];
    EXPECT_EQ(levels, json({{"relax", k.levels.at("relax")}, {"scheme", k.levels.at("scheme")}}));
    EXPECT_TRUE(levels["relax"].is_string());  // the level's text, as the JSON wrote the number
    hashes.insert(j.hash);
  }
  EXPECT_EQ(hashes.size(), 16u);
  EXPECT_EQ(ex.jobs[0].hash, ex.jobs[4].hash);  // series 0 and 1: the same configuration's jobs
}

TEST(ExternalFactors, OneAtATimeVariesEachFactorAloneFromTheBaseline) {
  const auto dir = factor_study_dir("one_at_a_time");
  json doc = factor_study();
  doc["factors"]["relax"] = {0.5, 0.7, 1};
  doc["design"] = json::parse(R"J({"one_at_a_time": {"scheme": "linearUpwind grad(U)", "relax": 0.7}})J");
  const Study s = parse_study_document(doc, dir);
  const auto configs = external_configurations(s);
  // The baseline, then each other level alone: 1 + (3 − 1) + (2 − 1).
  ASSERT_EQ(configs.size(), 4u);
  EXPECT_EQ(configs[0].levels, (std::map<std::string, std::string>{{"relax", "0.7"}, {"scheme", "linearUpwind grad(U)"}}));
  EXPECT_EQ(configs[1].levels, (std::map<std::string, std::string>{{"relax", "0.5"}, {"scheme", "linearUpwind grad(U)"}}));
  EXPECT_EQ(configs[3].levels, (std::map<std::string, std::string>{{"relax", "0.7"}, {"scheme", "QUICK"}}));
  EXPECT_EQ(s.design_description(), "one_at_a_time (baseline poly relax=0.7 scheme=linearUpwind grad(U))");
  EXPECT_EQ(expand(s).series.size(), 8u);
}

TEST(ExternalFactors, LevelTextIsWhatTheFileGets) {
  const auto dir = factor_study_dir("text");
  json doc = factor_study();
  doc["factors"]["relax"] = json::parse("[1e-5, 3, 2.50]");
  const ExpandedStudy ex = expand(parse_study_document(doc, dir));
  std::set<std::string> relax;
  for (const auto& k : ex.series) relax.insert(k.levels.at("relax"));
  EXPECT_EQ(relax, (std::set<std::string>{"1e-05", "3", "2.5"}));
}

TEST(ExternalFactors, ProblemsNameTheFactorAndWhy) {
  const auto dir = factor_study_dir("problems");
  auto with = [](const std::string& factors) {  // besides the template's scheme and relax
    json doc = factor_study();
    doc["factors"].update(json::parse(factors));
    return doc;
  };
  auto missing = problems_of(with(R"({"scheme": ["a"], "turbulence": ["kEpsilon"]})"), dir);
  EXPECT_TRUE(has_problem(missing, "/factors/turbulence", "@@turbulence@@")) << all_problems(missing);
  EXPECT_TRUE(has_problem(missing, "/factors/turbulence", "input.txt")) << all_problems(missing);
  auto grid = problems_of(with(R"({"N": [1, 2]})"), dir);
  EXPECT_TRUE(has_problem(grid, "/factors/N", "grid variable")) << all_problems(grid);
  auto derived = problems_of(with(R"({"h_cell": [1, 2]})"), dir);
  EXPECT_TRUE(has_problem(derived, "/factors/h_cell", "derived variable")) << all_problems(derived);
  auto cores = problems_of(with(R"({"cores": [1, 2]})"), dir);
  EXPECT_TRUE(has_problem(cores, "/factors/cores", "cores")) << all_problems(cores);
  auto twice = problems_of(with(R"({"scheme": ["QUICK", "QUICK"]})"), dir);
  EXPECT_TRUE(has_problem(twice, "/factors/scheme/1", "listed twice")) << all_problems(twice);
  auto boolean = problems_of(with(R"({"scheme": [true]})"), dir);
  EXPECT_FALSE(boolean.empty());
  json baseline = factor_study();
  baseline["design"] = json::parse(R"({"one_at_a_time": {"scheme": "MUSCL", "other": 1}})");
  auto b = problems_of(baseline, dir);
  EXPECT_TRUE(has_problem(b, "/design/one_at_a_time/scheme", "not a level")) << all_problems(b);
  EXPECT_TRUE(has_problem(b, "/design/one_at_a_time/other", "relax, scheme")) << all_problems(b);
}

TEST(ExternalFactors, EnsembleOfInstancesMadeWithExtends) {
  const auto dir = factor_study_dir("ensemble");
  json doc = factor_study();
  doc["cases"]["poly2"] = json::parse(R"({"extends": "poly", "external": {"variables": {"h_cell": "1.01 / N"}}})");
  doc["cases"]["poly3"] = json::parse(R"({"extends": "poly", "external": {"variables": {"h_cell": "0.99 / N"}}})");
  doc["ensembles"] = json::parse(R"({"inst": ["poly", "poly2", "poly3"]})");
  const Study s = parse_study_document(doc, dir);
  EXPECT_EQ(s.ensembles.at("inst").size(), 3u);
  const ExpandedStudy ex = expand(s);
  EXPECT_EQ(ex.series.size(), 24u);  // 3 instances × 4 configurations × 2 quantities
  EXPECT_EQ(distinct_job_count(ex), 48u);
}

// A case's constants (text placeholders of its own): an instance made with
// `extends` changes one, e.g. its snapshot file.
TEST(ExternalFactors, ConstantsAreACasesOwnTextPlaceholders) {
  const auto dir = factor_study_dir("constants");
  std::ofstream(dir / "poly/input.txt", std::ios::app) << "snapshot @@snapshot@@\n";
  json doc = factor_study();
  doc["cases"]["poly"]["external"]["constants"] = {{"snapshot", "t1.dat"}};
  doc["cases"]["poly2"] = json::parse(R"({"extends": "poly", "external": {"constants": {"snapshot": "t2.dat"}}})");
  doc["ensembles"] = json::parse(R"({"snapshots": ["poly", "poly2"]})");
  const ExpandedStudy ex = expand(parse_study_document(doc, dir));
  std::set<std::string> texts, hashes;
  for (const auto& j : ex.jobs) {
    texts.insert(j.doc["case"]["external"]["constants"]["snapshot"].get<std::string>());
    hashes.insert(j.hash);
  }
  EXPECT_EQ(texts, (std::set<std::string>{"t1.dat", "t2.dat"}));
  EXPECT_EQ(hashes.size(), 32u);  // 2 instances × 4 configurations × 4 grids
  json clash = doc;
  clash["cases"]["poly"]["external"]["constants"]["N"] = 3;
  auto p = problems_of(clash, dir);
  EXPECT_TRUE(has_problem(p, "/cases/poly/external/constants/N", "grid or derived variable")) << all_problems(p);
  json factor = doc;
  factor["factors"]["snapshot"] = {"a", "b"};
  p = problems_of(factor, dir);
  EXPECT_TRUE(has_problem(p, "/factors/snapshot", "constant of case poly")) << all_problems(p);
  json missing = doc;
  missing["cases"]["poly"]["external"].erase("constants");
  missing["cases"].erase("poly2");
  missing.erase("ensembles");
  p = problems_of(missing, dir);
  EXPECT_FALSE(p.empty());  // @@snapshot@@ defined by nothing
}

}  // namespace external_factors_test
}  // namespace gridfree
