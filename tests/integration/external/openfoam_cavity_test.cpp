// SPDX-License-Identifier: GPL-3.0-or-later
// The lid-driven cavity (tests/fixtures/external/cavity: icoFoam, Re 10,
// N x N x 1 cells, Courant number 1, end time 1 s, when the flow is steady)
// run by `gridfree-worker solve` through Debian's OpenFOAM: converged results
// carrying the volume-averaged |U|^2, a FOAM FATAL error classified failed
// with its line, a template edited after planning refused, and `collect`
// giving the same numbers without running again.
// OpenFOAM must be installed (scripts/install-deps.sh test installs it):
// without it these tests fail, they do not skip.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "job/template_hash.h"
#include "openfoam_present.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kCavity = fs::path(GRIDFREE_SOURCE_DIR) / "tests/fixtures/external/cavity";

json cavity_job(const fs::path& template_dir, int n) {
  return {{"schema", "gridfree/job/1"},
          {"case",
           {{"name", "cavity"},
            {"external",
             {{"template_dir", template_dir.string()},
              {"template_sha256", template_sha256(template_dir)},
              {"render", {"system/blockMeshDict", "system/controlDict"}},
              {"variables", {{"N", n}, {"dt", 0.1 / n}, {"end_time", 1}}},
              {"setup", {"export WM_PROJECT_DIR=/usr/share/openfoam"}},
              {"command", {"sh", "-c", "blockMesh && icoFoam > log.icoFoam 2>&1"}},
              {"version", "openfoam v1912"},
              {"collect",
               {{"quantities",
                 {{"mean_u2",
                   {{"units", "m^2/s^2"},
                    {"description", "volume average of |U|^2"},
                    {"file", "postProcessing/*/0/volFieldValue.dat"},
                    {"column", 1}}}}},
                {"failure_patterns", {"FOAM FATAL"}},
                {"residual",
                 {{"log", "log.icoFoam"}, {"regex", "Solving for Ux, Initial residual = ([-+0-9.eE]+)"}, {"tolerance", 1e-8}}},
                {"steady_tolerance", 1e-6}}}}}}},
          {"numerics", {{"grid", {{"level", 0}, {"h", 0.1 / n}, {"cells", n * n}}}}}};
}

struct CavityRun {
  int code = -1;
  json result;
  fs::path dir;
  std::string err;
};

CavityRun run_cavity(const std::string& name, const json& job, const std::string& verb = "solve") {
  CavityRun r;
  r.dir = test_support::scratch_root("external_openfoam") / name;
  fs::create_directories(r.dir);
  test_support::save_json(r.dir / "job.json", job);
  const auto out = r.dir / (verb + ".json");
  const auto ran = test_support::run_executable(
      "gridfree-worker", verb + " " + (r.dir / "job.json").string() + " -o " + out.string() + " -q", r.dir);
  r.code = ran.exit_code;
  r.err = ran.err;
  if (fs::exists(out)) r.result = test_support::load_json(out);
  return r;
}

class OpenFoamCavity : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(test_support::openfoam_present())
        << "OpenFOAM (icoFoam, blockMesh, /usr/share/openfoam) is not installed: run scripts/install-deps.sh test";
  }
};

// Volume-averaged |U|^2 at t = 1 s, from the same case run by hand
// (blockMesh && icoFoam) with OpenFOAM v1912; written with 9 significant
// digits. The tolerance 1e-6 (relative) leaves room for another CPU's
// rounding in linear solves converged to 1e-10 and is far below the change
// between neighbouring grids (5 % from N 12 to 16).
TEST_F(OpenFoamCavity, ConvergedOnThreeGridsWithTheQuantity) {
  const std::pair<int, double> grids[] = {{8, 5.22595754e-02}, {12, 5.87262216e-02}, {16, 6.16451979e-02}};
  for (const auto& [n, expected] : grids) {
    const auto r = run_cavity("grid" + std::to_string(n), cavity_job(kCavity, n));
    ASSERT_EQ(r.code, 0) << "N " << n << ": " << r.err << r.result.dump(2);
    EXPECT_EQ(r.result["status"], "converged") << r.result.value("reason", "");
    const double got = r.result["quantities"]["mean_u2"].get<double>();
    EXPECT_NEAR(got, expected, 1e-6 * expected) << "N " << n;
    EXPECT_DOUBLE_EQ(r.result["grid"]["h"].get<double>(), 0.1 / n);
    EXPECT_EQ(r.result["extra"]["external_version"], "openfoam v1912");
    std::cout << "cavity N " << n << ": mean_u2 " << got << ", wall " << r.result["timing"]["wall_s"] << " s, cpu "
              << r.result["timing"]["cpu_s"] << " s, peak " << r.result["memory"]["peak_rss_mb"] << " MiB\n";
  }
}

TEST_F(OpenFoamCavity, FoamFatalClassifiedFailedWithTheLine) {
  const auto tmpl = test_support::fresh_scratch_dir("external_openfoam", "broken_template");
  fs::copy(kCavity, tmpl, fs::copy_options::recursive);
  // fvSchemes without div(phi,U): icoFoam stops with FOAM FATAL IO ERROR.
  std::string schemes = test_support::slurp(tmpl / "system/fvSchemes");
  const auto at = schemes.find("div(phi,U)");
  ASSERT_NE(at, std::string::npos);
  schemes.replace(at, std::string("div(phi,U)").size(), "div(phi,V)");
  std::ofstream(tmpl / "system/fvSchemes") << schemes;
  const auto r = run_cavity("broken", cavity_job(tmpl, 8));
  EXPECT_EQ(r.code, 3) << r.err;
  EXPECT_EQ(r.result.value("status", ""), "failed");
  const std::string reason = r.result.value("reason", "");
  EXPECT_EQ(reason.rfind("failure pattern \"FOAM FATAL\" at line ", 0), 0u) << reason;
  EXPECT_NE(reason.find(" of log.icoFoam: "), std::string::npos) << reason;
  EXPECT_NE(reason.find("div(phi,U)"), std::string::npos) << reason;  // what OpenFOAM said was missing
  EXPECT_NE(r.result["extra"]["exit_code"], 0);
}

TEST_F(OpenFoamCavity, TemplateEditedAfterPlanningIsRefused) {
  const auto tmpl = test_support::fresh_scratch_dir("external_openfoam", "edited_template");
  fs::copy(kCavity, tmpl, fs::copy_options::recursive);
  const json job = cavity_job(tmpl, 8);
  std::ofstream(tmpl / "constant/transportProperties", std::ios::app) << "// nu to be changed\n";
  const auto r = run_cavity("edited", job);
  EXPECT_EQ(r.code, 3);
  EXPECT_EQ(r.result.value("reason", "").rfind("template changed since the job was planned", 0), 0u)
      << r.result.value("reason", "");
}

TEST_F(OpenFoamCavity, CollectGivesTheSameNumbersWithoutRunning) {
  const auto solved = run_cavity("collect", cavity_job(kCavity, 12));
  ASSERT_EQ(solved.code, 0) << solved.err;
  const auto log = solved.dir / "case/log.icoFoam";
  const auto before = fs::last_write_time(log);
  const auto collected = run_cavity("collect", cavity_job(kCavity, 12), "collect");
  ASSERT_EQ(collected.code, 0) << collected.err;
  EXPECT_EQ(collected.result["quantities"], solved.result["quantities"]);
  EXPECT_EQ(collected.result["status"], "converged");
  EXPECT_EQ(collected.result["timing"], solved.result["timing"]);
  EXPECT_EQ(fs::last_write_time(log), before) << "collect ran the case again";
}

}  // namespace
}  // namespace gridfree
