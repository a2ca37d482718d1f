// SPDX-License-Identifier: GPL-3.0-or-later
// External cases in studies (study/external_case.h): validation problems
// with their JSON paths, and expansion (h, variables, jobs per grid, series
// per quantity, what the job hash does and does not follow).
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "project_paths.h"
#include "scratch_dir.h"
#include "study/study.h"

namespace gridfree {
namespace {

using nlohmann::json;

// A study folder holding a copy of the poly test solver's template.
std::filesystem::path poly_study_dir(const std::string& name) {
  const auto dir = test_support::fresh_scratch_dir("external_study", name);
  std::filesystem::copy(test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
                        std::filesystem::copy_options::recursive);
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

std::vector<Problem> problems_of(const json& doc, const std::filesystem::path& dir) {
  try {
    parse_study_document(doc, dir);
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

void write_file(const std::filesystem::path& f, const std::string& text) {
  std::ofstream(f, std::ios::binary) << text;
}

TEST(ExternalStudy, ExpandsOneJobPerGridAndOneSeriesPerQuantity) {
  const auto dir = poly_study_dir("expand");
  const Study s = parse_study_document(poly_study(), dir);
  ASSERT_TRUE(s.external());
  const ExpandedStudy ex = expand(s);
  ASSERT_EQ(ex.series.size(), 2u);
  EXPECT_EQ(ex.series[0].quantity, "f");
  EXPECT_EQ(ex.series[1].quantity, "h_echo");
  EXPECT_EQ(ex.series[0].label(), "poly f");
  ASSERT_EQ(ex.jobs.size(), 8u);  // 4 grids, each in both series
  const std::vector<double> n = {4, 6, 8, 12};
  for (std::size_t g = 0; g < 4; ++g) {
    const StudyJob& job = ex.jobs[g];
    EXPECT_EQ(job.series, 0u);
    EXPECT_EQ(job.grid, g);
    EXPECT_DOUBLE_EQ(job.delta_star, 1 / n[g]);
    EXPECT_EQ(job.cells[0], static_cast<int>(n[g] * n[g]));
    const json& e = job.doc["case"]["external"];
    EXPECT_EQ(e["variables"]["N"].get<double>(), n[g]);
    EXPECT_DOUBLE_EQ(e["variables"]["h_cell"].get<double>(), 1 / n[g]);
    EXPECT_EQ(e["template_dir"].get<std::string>(), (dir / "poly").string());
    EXPECT_EQ(e["template_sha256"].get<std::string>().size(), 64u);
    EXPECT_EQ(e["version"], "poly 1");
    EXPECT_EQ(job.doc["numerics"]["grid"]["level"], g);
    EXPECT_DOUBLE_EQ(job.doc["numerics"]["grid"]["h"].get<double>(), 1 / n[g]);
    EXPECT_EQ(ex.jobs[g + 4].hash, job.hash);  // the second quantity's series reads the same job
    for (std::size_t k = 0; k < g; ++k) EXPECT_NE(ex.jobs[k].hash, job.hash);
  }
}

TEST(ExternalStudy, HVolumeFormIsVolumePerCellToOneOverDim) {
  const auto dir = poly_study_dir("volume");
  json doc = poly_study();
  doc["cases"]["poly"]["external"]["h"] = {{"cells", "N * N"}, {"volume", 0.01}, {"dim", 2}};
  doc["cases"]["poly"]["external"].erase("cells");
  const ExpandedStudy ex = expand(parse_study_document(doc, dir));
  EXPECT_DOUBLE_EQ(ex.jobs[2].delta_star, 0.1 / 8);  // sqrt(0.01 / 64)
  EXPECT_EQ(ex.jobs[2].cells[0], 64);
}

TEST(ExternalStudy, HashFollowsTemplateAndVersionNotCollectOrPlace) {
  const auto dir = poly_study_dir("hash");
  const auto hashes = [&](const json& doc) {
    std::vector<std::string> out;
    for (const auto& j : expand(parse_study_document(doc, dir)).jobs) out.push_back(j.hash);
    return out;
  };
  const auto base = hashes(poly_study());
  json collect = poly_study();
  collect["cases"]["poly"]["external"]["collect"]["quantities"]["f"]["column"] = 0;
  collect["cases"]["poly"]["external"]["collect"]["failure_patterns"] = {"FATAL"};
  EXPECT_EQ(hashes(collect), base);
  json version = poly_study();
  version["cases"]["poly"]["external"]["version"] = "poly 2";
  const auto v2 = hashes(version);
  for (std::size_t i = 0; i < base.size(); ++i) EXPECT_NE(v2[i], base[i]);
  // The template moved elsewhere: the same jobs.
  std::filesystem::rename(dir / "poly", dir / "moved");
  json moved = poly_study();
  moved["cases"]["poly"]["external"]["template"] = "moved";
  EXPECT_EQ(hashes(moved), base);
  // A template file edited: every job is new.
  write_file(dir / "moved/solve.sh", "#!/bin/sh\necho edited\n");
  const auto edited = hashes(moved);
  for (std::size_t i = 0; i < base.size(); ++i) EXPECT_NE(edited[i], base[i]);
}

TEST(ExternalStudy, VersionCommandsFirstLineIsTheVersion) {
  const auto dir = poly_study_dir("version");
  json doc = poly_study();
  doc["cases"]["poly"]["external"].erase("version");
  doc["cases"]["poly"]["external"]["version_command"] = "printf 'poly 7.1\\nbuilt today\\n'";
  const ExpandedStudy ex = expand(parse_study_document(doc, dir));
  EXPECT_EQ(ex.jobs[0].doc["case"]["external"]["version"], "poly 7.1");
}

struct ExternalRefusal {
  const char* name;
  std::function<void(json&, const std::filesystem::path&)> edit;
  std::string where, reason_part;
};

TEST(ExternalStudy, ProblemsNameTheirPathAndReason) {
  const std::string at = "/cases/poly/external";
  const std::vector<ExternalRefusal> table = {
      {"template missing", [](json& d, auto&) { d["cases"]["poly"]["external"]["template"] = "nowhere"; },
       at + "/template", "template folder 'nowhere' not found"},
      {"render file missing", [](json& d, auto&) { d["cases"]["poly"]["external"]["render"] = {"system/none"}; },
       at + "/render/0", "'system/none' is not a file of the template folder"},
      {"render outside", [](json& d, auto&) { d["cases"]["poly"]["external"]["render"] = {"../x"}; },
       at + "/render/0", "must be a path inside the template folder"},
      {"undefined placeholder",
       [](json&, const std::filesystem::path& dir) { write_file(dir / "poly/input.txt", "N @@N@@\n\ndt @@dt@@\n"); },
       at + "/render/0", "input.txt line 3: placeholder @@dt@@ is not a defined variable"},
      {"bad expression", [](json& d, auto&) { d["cases"]["poly"]["external"]["variables"]["h_cell"] = "1 / (N"; },
       at + "/variables/h_cell", "expression '1 / (N': at position 7: expected ')'"},
      {"number for an expression (schema; no crash)",
       [](json& d, auto&) { d["cases"]["poly"]["external"]["variables"]["h_cell"] = 0.5; },
       at + "/variables/h_cell", ""},
      {"unknown name", [](json& d, auto&) { d["cases"]["poly"]["external"]["h"] = "L / N"; },
       at + "/h", "reads 'L', which is not a variable (defined: N, h_cell)"},
      {"h not distinct", [](json& d, auto&) { d["cases"]["poly"]["external"]["h"] = "min(N, 6)"; },
       at + "/h", "on grids 1 and 2; every grid needs its own h"},
      {"h negative", [](json& d, auto&) { d["cases"]["poly"]["external"]["h"] = "-1 / N"; },
       at + "/h", "it must be a positive finite number"},
      {"derived infinite", [](json& d, auto&) { d["cases"]["poly"]["external"]["variables"]["h_cell"] = "1 / (N - 6)"; },
       at + "/variables/h_cell", "is inf on grid 1, not a finite number"},
      {"cycle", [](json& d, auto&) {
         d["cases"]["poly"]["external"]["variables"]["a"] = "b";
         d["cases"]["poly"]["external"]["variables"]["b"] = "a";
       }, at, "depend on each other in a cycle"},
      {"shadowing", [](json& d, auto&) { d["cases"]["poly"]["external"]["variables"]["N"] = "2"; },
       at + "/variables/N", "already a grid variable"},
      {"empty program", [](json& d, auto&) { d["cases"]["poly"]["external"]["command"] = {""}; },
       at + "/command", "needs a program name"},
      {"no units", [](json& d, auto&) { d["cases"]["poly"]["external"]["collect"]["quantities"]["f"]["units"] = ""; },
       at + "/collect/quantities/f/units", "units are required"},
      {"no column", [](json& d, auto&) { d["cases"]["poly"]["external"]["collect"]["quantities"]["f"].erase("column"); },
       at + "/collect/quantities/f/file", "needs its column"},
      {"both versions", [](json& d, auto&) { d["cases"]["poly"]["external"]["version_command"] = "echo 1"; },
       at, "give exactly one of version and version_command"},
      {"failing version command", [](json& d, auto&) {
         d["cases"]["poly"]["external"].erase("version");
         d["cases"]["poly"]["external"]["version_command"] = "exit 3";
       }, at + "/version_command", "'exit 3': the command failed (exit code 3)"},
      {"uneven grid variables", [](json& d, auto&) { d["grids"]["variables"]["M"] = {1, 2}; },
       "/grids/variables", "the grid variables have different lengths (M 2, N 4); each needs one value per grid"},
      {"physical grids", [](json& d, auto&) { d["grids"] = {{"delta_star", {4, 2}}}; },
       "/grids", "external cases take their grids as"},
      {"factor not in the template", [](json& d, auto&) { d["factors"] = {{"drag", {"bvk"}}}; },
       "/factors/drag", "no rendered file of case poly (input.txt) has the placeholder @@drag@@"},
      {"numerics", [](json& d, auto&) { d["numerics"] = {{"max_iterations", 10}}; },
       "/numerics", "does not apply to external cases"},
      {"mixed cases", [](json& d, auto&) {
         d["cases"]["PC1"] = {{"domain_dp", {30, 200, 10}}, {"particle_diameter_cm", 0.01},
                              {"particles", {{"generator", {{"kind", "bursting_bubble"}}}}}};
       }, "/cases", "either all external or all physical"},
  };
  for (const auto& r : table) {
    SCOPED_TRACE(r.name);
    const auto dir = poly_study_dir("refusal");
    json doc = poly_study();
    r.edit(doc, dir);
    const auto problems = problems_of(doc, dir);
    ASSERT_FALSE(problems.empty());
    bool found = false;
    for (const auto& p : problems)
      if (p.where == r.where && p.reason.find(r.reason_part) != std::string::npos) found = true;
    EXPECT_TRUE(found) << InputError(problems).what();
  }
}

// The cores rule (study/job_cores.h) in an external study: not part of any
// job's identity; @@cores@@ defined in every rendered file; a variable may
// not be named cores; the rule needs the case's cells.
TEST(ExternalStudy, CoresRuleKeepsHashesAndDefinesTheCoresPlaceholder) {
  const auto dir = poly_study_dir("cores");
  const auto hashes = [&](const json& doc) {
    std::vector<std::string> out;
    for (const auto& j : expand(parse_study_document(doc, dir)).jobs) out.push_back(j.hash);
    return out;
  };
  const auto base = hashes(poly_study());
  json with = poly_study();
  with["cores"] = "max(1, cells / 50)";
  EXPECT_EQ(hashes(with), base);
  // The template may use @@cores@@ (an undefined placeholder is refused).
  write_file(dir / "poly/input.txt", "N @@N@@\nh @@h_cell@@\nranks @@cores@@\n");
  EXPECT_NO_THROW(parse_study_document(with, dir));
  write_file(dir / "poly/input.txt", "N @@N@@\nh @@h_cell@@\nranks @@ranks@@\n");
  const auto undefined = problems_of(with, dir);
  ASSERT_FALSE(undefined.empty());
  EXPECT_NE(undefined[0].reason.find("@@ranks@@"), std::string::npos) << InputError(undefined).what();
}

TEST(ExternalStudy, CoresRuleRefusals) {
  struct Row {
    const char* name;
    void (*edit)(json&);
    std::string where, reason_part;
  };
  const std::string at = "/cases/poly/external";
  const std::vector<Row> table = {
      {"derived variable named cores", [](json& d) { d["cases"]["poly"]["external"]["variables"]["cores"] = "N"; },
       at + "/variables/cores", "'cores' is the job's number of cores"},
      {"grid variable named cores", [](json& d) { d["grids"]["variables"]["cores"] = {1, 2, 3, 4}; },
       "/grids/variables/cores", "'cores' is the job's number of cores"},
      {"reads a grid variable", [](json& d) { d["cores"] = "N / 2"; }, "/cores", "reads 'N'"},
      {"no cells", [](json& d) {
         d["cores"] = "cells / 10";
         d["cases"]["poly"]["external"].erase("cells");
       }, "/cores", "does not say how many cells"},
      {"infinite on a grid", [](json& d) { d["cores"] = "1 / (cells - 36)"; },  // N = 6: 36 cells
       "/cores", "is inf at 36 cells (case 'poly', grid 1)"},
  };
  for (const auto& r : table) {
    SCOPED_TRACE(r.name);
    const auto dir = poly_study_dir("cores_refusal");
    json doc = poly_study();
    r.edit(doc);
    const auto problems = problems_of(doc, dir);
    ASSERT_FALSE(problems.empty());
    bool found = false;
    for (const auto& p : problems)
      if (p.where == r.where && p.reason.find(r.reason_part) != std::string::npos) found = true;
    EXPECT_TRUE(found) << InputError(problems).what();
  }
}

}  // namespace
}  // namespace gridfree
