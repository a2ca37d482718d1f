// SPDX-License-Identifier: GPL-3.0-or-later
// The driver's case folder (external/external_driver.h prepare_external_case):
// @@cores@@ is the job's cores (the worker's --threads), for decomposePar
// and mpirun -np; a variable the job itself names cores wins.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "external/external_driver.h"
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

}  // namespace
}  // namespace gridfree
