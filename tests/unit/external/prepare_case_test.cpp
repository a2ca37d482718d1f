// SPDX-License-Identifier: GPL-3.0-or-later
// The driver's case folder (external/external_driver.h prepare_external_case):
// @@cores@@ is the job's cores (the worker's --threads), for decomposePar
// and mpirun -np; a variable the job itself names cores wins.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "external/external_driver.h"
#include "external/external_job.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

std::string read_text(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ExternalJob job_in(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "template/system");
  std::ofstream(dir / "template/system/decomposeParDict", std::ios::binary)
      << "numberOfSubdomains @@cores@@;\nn @@N@@;\n";
  ExternalJob job;
  job.template_dir = dir / "template";
  job.render = {"system/decomposeParDict"};
  job.variables = {{"N", 64}};
  return job;
}

TEST(ExternalPrepareCase, CoresPlaceholderIsTheJobsCores) {
  const auto dir = test_support::fresh_scratch_dir("prepare_case", "cores");
  const ExternalJob job = job_in(dir);
  prepare_external_case(job, dir / "run2", 2);
  EXPECT_EQ(read_text(dir / "run2/case/system/decomposeParDict"), "numberOfSubdomains 2;\nn 64;\n");
  prepare_external_case(job, dir / "run1");  // one core unless told
  EXPECT_EQ(read_text(dir / "run1/case/system/decomposeParDict"), "numberOfSubdomains 1;\nn 64;\n");
}

TEST(ExternalPrepareCase, AJobsOwnCoresVariableWins) {
  const auto dir = test_support::fresh_scratch_dir("prepare_case", "own");
  ExternalJob job = job_in(dir);
  job.variables.emplace_back("cores", 6);
  prepare_external_case(job, dir / "run", 2);
  EXPECT_EQ(read_text(dir / "run/case/system/decomposeParDict"), "numberOfSubdomains 6;\nn 64;\n");
}

// A factor level and a case constant (docs/EXTERNAL.md "Factors, designs
// and ensembles") are written as their text, spaces and parentheses
// included; numbers as before.
TEST(ExternalPrepareCase, FactorLevelsAreWrittenAsTheirText) {
  const auto dir = test_support::fresh_scratch_dir("prepare_case", "levels");
  std::filesystem::create_directories(dir / "template/system");
  std::ofstream(dir / "template/system/fvSchemes", std::ios::binary) << "div(phi,T) @@scheme@@;\nn @@N@@;\nfile @@snapshot@@;\n";
  const nlohmann::json doc = {
      {"schema", "gridfree/job/1"},
      {"case",
       {{"name", "c"},
        {"external",
         {{"template_dir", (dir / "template").string()},
          {"template_sha256", std::string(64, '0')},
          {"render", {"system/fvSchemes"}},
          {"variables", {{"N", 8}}},
          {"levels", {{"scheme", "Gauss linearUpwind grad(T)"}}},
          {"constants", {{"snapshot", "t2.dat"}}},
          {"command", {"true"}},
          {"version", "1"},
          {"collect", {{"quantities", {{"q", {{"units", "1"}, {"log", "stdout"}, {"regex", "q=(.*)"}}}}}}}}}}}};
  const ExternalJob job = parse_external_job(doc, dir);
  ASSERT_EQ(job.levels.size(), 2u);  // the constant and the level
  prepare_external_case(job, dir / "run", 1);
  EXPECT_EQ(read_text(dir / "run/case/system/fvSchemes"),
            "div(phi,T) Gauss linearUpwind grad(T);\nn 8;\nfile t2.dat;\n");
  nlohmann::json bad = doc;
  bad["case"]["external"]["levels"]["N"] = "3";  // a placeholder has one value
  EXPECT_THROW(parse_external_job(bad, dir), InputError);
  bad = doc;
  bad["case"]["external"]["levels"]["scheme"] = 2;  // levels are text
  EXPECT_THROW(parse_external_job(bad, dir), InputError);
}

}  // namespace
}  // namespace gridfree
