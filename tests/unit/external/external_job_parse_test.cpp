// SPDX-License-Identifier: GPL-3.0-or-later
// parse_external_job: a full job read back field by field, and problems
// named by their JSON pointers (all of them at once).
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "external/external_job.h"

namespace gridfree {
namespace {

nlohmann::json external_job_doc() {
  return nlohmann::json::parse(R"J({
    "schema": "gridfree/job/1",
    "case": {"name": "cavity", "external": {
      "template_dir": "tmpl",
      "template_sha256": "0123456789abcdef0123456789abcdef0123456789abcdef0123456789abcdef",
      "render": ["system/blockMeshDict"],
      "variables": {"N": 16, "dt": 0.00625},
      "setup": ["export WM_PROJECT_DIR=/usr/share/openfoam"],
      "command": ["sh", "-c", "blockMesh && icoFoam"],
      "version": "openfoam v1912",
      "collect": {
        "quantities": {
          "ke": {"units": "m^2/s^2", "description": "mean", "file": "post/*/v.dat", "column": 1},
          "ux": {"log": "log.icoFoam", "regex": "ux = ([-+0-9.eE]+)"}},
        "failure_patterns": ["FOAM FATAL"],
        "residual": {"log": "log.icoFoam", "regex": "Ux, Initial residual = ([-+0-9.eE]+)", "tolerance": 1e-5},
        "steady_tolerance": 1e-6}}},
    "numerics": {"grid": {"level": 1, "h": 0.00625, "cells": 256}}})J");
}

std::vector<Problem> external_parse_problems(const nlohmann::json& doc) {
  try {
    (void)parse_external_job(doc, "/runs/x");
  } catch (const InputError& e) {
    return e.problems();
  }
  return {};
}

bool has_problem_at(const std::vector<Problem>& problems, const std::string& where) {
  for (const auto& p : problems)
    if (p.where == where) return true;
  return false;
}

TEST(ExternalJobParse, ReadsEveryField) {
  const auto doc = external_job_doc();
  ASSERT_TRUE(is_external_job(doc));
  const auto job = parse_external_job(doc, "/runs/x");
  EXPECT_EQ(job.name, "cavity");
  EXPECT_EQ(job.template_dir, std::filesystem::path("/runs/x/tmpl"));
  EXPECT_EQ(job.render, std::vector<std::string>{"system/blockMeshDict"});
  ASSERT_EQ(job.variables.size(), 2u);
  EXPECT_EQ(job.command.size(), 3u);
  EXPECT_EQ(job.version, "openfoam v1912");
  ASSERT_EQ(job.collect.quantities.size(), 2u);
  EXPECT_EQ(job.collect.quantities[0].name, "ke");
  EXPECT_EQ(job.collect.quantities[0].column, 1);
  EXPECT_EQ(job.collect.quantities[1].regex, "ux = ([-+0-9.eE]+)");
  ASSERT_TRUE(job.collect.residual);
  EXPECT_DOUBLE_EQ(job.collect.residual->tolerance, 1e-5);
  EXPECT_DOUBLE_EQ(*job.collect.steady_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(*job.grid_h, 0.00625);
  EXPECT_FALSE(is_external_job(nlohmann::json::parse(R"({"case": {"name": "bed"}})")));
}

TEST(ExternalJobParse, ProblemsNamedByJsonPointer) {
  auto doc = external_job_doc();
  auto& ext = doc["case"]["external"];
  ext["template_sha256"] = "abc";
  ext["render"] = {"../outside"};
  ext["variables"]["2x"] = 1;
  ext["variables"]["dt"] = "fast";
  ext["command"] = nlohmann::json::array();
  ext["collect"]["quantities"]["ke"]["column"] = -1;
  ext["collect"]["quantities"]["ux"]["regex"] = "no group";
  ext["collect"]["quantities"]["both"] = {{"file", "a"}, {"column", 0}, {"log", "b"}, {"regex", "(x)"}};
  ext["collect"]["failure_patterns"] = {"[unclosed"};
  ext["collect"]["residual"].erase("tolerance");
  ext["collect"]["steady_tolerance"] = 0;
  ext["colect"] = 1;
  const auto problems = external_parse_problems(doc);
  for (const char* where :
       {"/case/external/template_sha256", "/case/external/render/0", "/case/external/variables/2x",
        "/case/external/variables/dt", "/case/external/command", "/case/external/collect/quantities/ke/column",
        "/case/external/collect/quantities/ux/regex", "/case/external/collect/quantities/both",
        "/case/external/collect/failure_patterns/0", "/case/external/collect/residual/tolerance",
        "/case/external/collect/steady_tolerance", "/case/external/colect"})
    EXPECT_TRUE(has_problem_at(problems, where)) << where << "\n" << format_problems(problems);
  EXPECT_EQ(problems.size(), 12u) << format_problems(problems);
}

TEST(ExternalJobParse, RequiredFields) {
  auto doc = external_job_doc();
  doc["case"]["external"].erase("template_dir");
  doc["case"]["external"].erase("command");
  const auto problems = external_parse_problems(doc);
  EXPECT_TRUE(has_problem_at(problems, "/case/external/template_dir"));
  EXPECT_TRUE(has_problem_at(problems, "/case/external/command"));
}

}  // namespace
}  // namespace gridfree
