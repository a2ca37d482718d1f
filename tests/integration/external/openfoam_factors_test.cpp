// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run` on the shipped OpenFOAM study with a factor and an
// ensemble (studies/external_scalar_transport.json, docs/EXTERNAL.md
// "Factors, designs and ensembles"): scalarTransportFoam, steady 1D
// convection-diffusion, the factor `scheme` (Gauss upwind, Gauss linear)
// × three instances of the diffusivity × 5 grids = 30 jobs. Checked: the
// series are keyed by their levels in the database (no particle-bed
// columns), every f0 is within its finest grid's U of the exact mean
// 1/Pe − 1/(e^Pe − 1), the report has the one-factor differences of the
// scheme and the ensemble budget, and a rerun reuses every job. Also: the
// shipped cavity study (no factors) keeps the job hashes it had before
// factors existed. OpenFOAM must be installed (scripts/install-deps.sh
// test installs it): without it these tests fail. Adaptive grids with a
// factor refine each configuration's own ladder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "openfoam_present.h"
#include "project_paths.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"

namespace openfoam_factors_test {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;
using nlohmann::json;

const fs::path kFactorsWorker = fs::path(GRIDFREE_BIN_DIR) / "gridfree-worker";

// The shipped study `name`.json with its templates under external/; each
// solver run appends its case folder to dir/starts.txt.
fs::path shipped_study_in(const std::string& test, const std::string& name, const std::string& count_case) {
  const auto dir = ts::fresh_scratch_dir("external_openfoam_factors", test);
  fs::copy(ts::kSourceDir / "studies/external", dir / "external", fs::copy_options::recursive);
  std::ifstream in(ts::kSourceDir / ("studies/" + name + ".json"));
  json doc = json::parse(in);
  if (!count_case.empty())
    doc["cases"][count_case]["external"]["setup"].push_back("echo \"$PWD\" >> " +
                                                            ts::shell_quote((dir / "starts.txt").string()));
  std::ofstream(dir / "study.json") << doc.dump(2);
  return dir;
}

ts::CommandRun run_gridfree(const fs::path& dir, const std::string& args) {
  return ts::gridfree_in(dir, args, "GRIDFREE_WORKER=" + ts::shell_quote(kFactorsWorker.string()));
}

std::size_t line_count(const fs::path& f) {
  std::ifstream in(f);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

class OpenFoamFactors : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ts::openfoam_present())
        << "OpenFOAM (icoFoam, blockMesh, /usr/share/openfoam) is not installed: run scripts/install-deps.sh test";
  }
};

TEST_F(OpenFoamFactors, SchemeFactorAndDiffusivityEnsembleEndToEnd) {
  // Every case extends pe10, so the counting setup line is in all of them.
  const auto dir = shipped_study_in("run", "external_scalar_transport", "pe10");
  const auto db = dir / "g.sqlite";
  const auto first = run_gridfree(dir, "run study.json -j 2 --db g.sqlite");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(line_count(dir / "starts.txt"), 30u);  // 3 instances × 2 schemes × 5 grids
  // Series keyed by case, levels and quantity; no particle-bed factors.
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM series"), "6");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT group_concat(s, '|') FROM (SELECT DISTINCT json_extract(levels, '$.scheme') "
                                 "AS s FROM series ORDER BY s)"),
            "Gauss linear|Gauss upwind");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM v_series WHERE quantity = 'T_mean' AND convection IS NULL AND "
                                 "fwhm_dp IS NULL AND drag IS NULL AND deposition IS NULL"),
            "6");
  // Each configuration's jobs carry its level: 15 jobs per scheme.
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE json_extract(spec_json, "
                                 "'$.case.external.levels.scheme') = 'Gauss linear'"),
            "15");
  // Every f0 within its finest grid's U of the exact 1/Pe − 1/(e^Pe − 1), Pe = 1/DT.
  const auto rows = ts::sqlite_query(db,
      "SELECT v.case_name, json_extract(v.levels, '$.scheme'), v.verdict, printf('%.17g %.17g', v.f0, v.finest_u) "
      "FROM v_series v ORDER BY v.series_id");
  const std::map<std::string, double> dt = {{"pe10", 0.1}, {"pe10_dt_plus", 0.102}, {"pe10_dt_minus", 0.098}};
  std::istringstream lines(rows);
  int checked = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::string case_name, scheme, verdict, numbers;
    std::getline(fields, case_name, '|');
    std::getline(fields, scheme, '|');
    std::getline(fields, verdict, '|');
    std::getline(fields, numbers);
    double f0 = 0, u = 0;
    std::istringstream(numbers) >> f0 >> u;
    const double pe = 1 / dt.at(case_name);
    const double exact = 1 / pe - 1 / std::expm1(pe);
    EXPECT_EQ(verdict, "converged") << line;
    EXPECT_LE(std::abs(f0 - exact), u) << line << " exact " << exact;
    ++checked;
  }
  EXPECT_EQ(checked, 6) << rows;
  // The report: one-factor differences of the scheme (one per instance) and the budget.
  const auto report = dir / "reports/external_scalar_transport";
  const std::string differences = ts::slurp(report / "differences.csv");
  std::size_t scheme_rows = 0;
  for (std::size_t at = differences.find("\nscheme,Gauss upwind,Gauss linear,"); at != std::string::npos;
       at = differences.find("\nscheme,Gauss upwind,Gauss linear,", at + 1))
    ++scheme_rows;
  EXPECT_EQ(scheme_rows, 3u) << differences;
  // series.csv names the case, the quantity, a column per factor and the levels, no particle-bed column.
  const std::string series_csv = ts::slurp(report / "series.csv");
  const std::string header = series_csv.substr(0, series_csv.find('\n'));
  EXPECT_NE(header.find(",case,quantity,scheme,levels,"), std::string::npos) << header;
  EXPECT_EQ(header.find("fwhm_dp"), std::string::npos) << header;
  EXPECT_NE(series_csv.find(",pe10,T_mean,Gauss linear,"), std::string::npos) << series_csv;
  const std::string budget = ts::slurp(report / "budget.csv");
  EXPECT_NE(budget.find("diffusivity: scheme=Gauss linear T_mean"), std::string::npos) << budget;
  EXPECT_NE(budget.find("scheme Gauss upwind vs Gauss linear"), std::string::npos) << budget;
  EXPECT_NE(ts::slurp(report / "report.md").find("differing only in one of the study's factors"), std::string::npos);
  // What a person reads speaks the case's words: no particle-bed term
  // (study/case_vocabulary.h), ensemble section and budget chart included.
  for (const char* page : {"report.md", "report.html", "budget_diffusivity.svg"})
    for (const char* word : {"Δ*", "particle", "drag", "filter width", "FM18", "DP*", "outer iteration", "ε_s"})
      EXPECT_EQ(ts::slurp(report / page).find(word), std::string::npos) << page << ": " << word;
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(DISTINCT levels) || ' ' || MIN(instances) FROM v_ensemble_budget"),
            "2 3");
  // A rerun reuses every job.
  const auto again = run_gridfree(dir, "run study.json -j 2 --db g.sqlite");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(line_count(dir / "starts.txt"), 30u) << "the rerun ran jobs again";
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM jobs"), "30");
}

// Adaptive grids with a factor: each configuration refines its own ladder
// (N = 40 → 1280, ratio 2) to the target RDE 0.5 %, its new grids carrying
// its level. Measured: linear (p ≈ 2) meets it at N = 640 (RDE 0.17 %),
// upwind (p ≈ 0.8) does not by N = 1280 (RDE 1.0 %).
TEST_F(OpenFoamFactors, AdaptiveGridsRefineEachConfigurationsOwnLadder) {
  const auto dir = ts::fresh_scratch_dir("external_openfoam_factors", "adaptive");
  fs::copy(ts::kSourceDir / "studies/external", dir / "external", fs::copy_options::recursive);
  std::ifstream in(ts::kSourceDir / "studies/external_scalar_transport.json");
  json doc = json::parse(in);
  doc["cases"].erase("pe10_dt_plus");
  doc["cases"].erase("pe10_dt_minus");
  doc.erase("ensembles");
  doc["grids"] = json::parse(R"({"target_rde": 0.005, "ratio": 2, "variables": {"N": {"coarsest": 40, "finest": 1280}}})");
  std::ofstream(dir / "study.json") << doc.dump(2);
  const auto run = run_gridfree(dir, "run study.json -j 2 --db g.sqlite");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(ts::sqlite_query(db, "SELECT json_extract(levels, '$.scheme') || ' ' || adaptive_status || ' ' || "
                                 "(SELECT COUNT(*) FROM study_jobs sj WHERE sj.series_id = series.id) FROM series "
                                 "ORDER BY id"),
            "Gauss upwind target_not_reached 6\nGauss linear target_met 5");
  // Every job of a series, the ladder's new ones included, has the series' level.
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM study_jobs sj JOIN series se ON se.id = sj.series_id JOIN jobs j "
                                 "ON j.id = sj.job_id WHERE json_extract(j.spec_json, '$.case.external.levels.scheme') "
                                 "<> json_extract(se.levels, '$.scheme')"),
            "0");
}

// Job hashes of studies/external_cavity.json on main before factors existed
// (commit 05ebd34, `gridfree submit`, Debian 12's OpenFOAM v1912).
TEST_F(OpenFoamFactors, ShippedCavityStudyKeepsItsJobHashes) {
  const auto dir = shipped_study_in("cavity_hashes", "external_cavity", "");
  const auto submitted = run_gridfree(dir, "submit study.json --db g.sqlite");
  ASSERT_EQ(submitted.exit_code, 0) << submitted.err;
  EXPECT_EQ(ts::sqlite_query(dir / "g.sqlite", "SELECT group_concat(job_hash, ' ') FROM (SELECT job_hash FROM jobs "
                                               "ORDER BY id)"),
            "440a1e66bab01f1ab3d73e992f02241186c87287b4ab80ddd044eb4c00ced065 "
            "94423a10d80b4374483f6c55f4e2be260fe25c562c171f9d8e494f2a920dbbdd "
            "c64645dfa18faf984956536d7bd06ab9497c383e2ee807617658fe145b48000c "
            "2fcf34557c53064ed40cc6aa85277d4d69705ac48706d4932900f5b6e04c9c60 "
            "976914d246e7a0d9a566befaa222325547c31af0048fd8c27fb630147fbe5a10");
}

}  // namespace openfoam_factors_test
