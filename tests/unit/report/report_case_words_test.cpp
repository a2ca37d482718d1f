// SPDX-License-Identifier: GPL-3.0-or-later
// The report speaks in the words of its case (study/case_vocabulary.h): an
// external study's report (an OpenFOAM-like cavity: its quantity, h = 0.1/N,
// a declared cell count, no iteration counts, no factors) is written end to
// end by write_study_report with the extrapolation library, and none of the
// particle bed's words appears in what a person reads (report.html,
// report.md, every SVG); the worker's own synthetic study still has them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "report/extrapolator.h"
#include "report/report.h"
#include "report_test_data.h"
#include "scratch_dir.h"
#include "test_files.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// The words of the particle bed (and its design words) an external report
// must not print.
const std::vector<std::string> kParticleWords = {"Δ*",     "particle",        "drag",       "filter width",
                                                 "FM18",   "DP*",             "fwhm",       "outer iteration",
                                                 "factorial", "per factor level", "ε_s", "numerics."};

// The cavity as the store hands it over: nx = cells, ny = nz = 1,
// iterations 0 (the code reports none); f = 0.0672 − 3 h^1.5 exactly, h = 0.1/N (converged).
StudyReportData cavity_study() {
  StudyReportData d;
  d.study_name = "cavity";
  d.status = "done";
  d.version = "gridfree (test)";
  d.baseline_description = "factorial";
  SeriesData s;
  s.id = 1;
  s.case_name = "cavity";
  s.status = "done";
  s.quantity = "mean_u2";
  s.quantity_label = "mean_u2: volume average of |U|^2 [m^2/s^2]";
  s.h_label = "h = 0.1 / N";
  for (int n : {20, 28, 40, 57, 80}) {
    GridPoint g;
    g.job_hash = "hash-" + std::to_string(n);
    g.delta_star = 0.1 / n;
    g.nx = n * n;
    g.ny = g.nz = 1;
    g.status = "converged";
    g.dp_star = 0.0672 - 3 * std::pow(g.delta_star, 1.5);
    g.wall_s = g.cpu_s = 1e-3 * n * n;
    g.peak_rss_mb = 100;
    s.grids.push_back(g);
  }
  d.series = {s};
  return d;
}

std::string readable_text(const fs::path& dir) {
  std::string all;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto ext = e.path().extension();
    if (ext == ".html" || ext == ".md" || ext == ".svg") all += test_support::slurp(e.path()) + "\n";
  }
  return all;
}

TEST(ReportCaseWords, AnExternalReportHasNoParticleWords) {
  const fs::path dir = test_support::fresh_scratch_dir("case_words", "external");
  StudyReportData d = cavity_study();
  d.export_charts = false;
  write_study_report(d, dir);
  const std::string text = readable_text(dir);
  ASSERT_NE(text.find("mean_u2"), std::string::npos);
  for (const auto& w : kParticleWords) EXPECT_EQ(text.find(w), std::string::npos) << w;
  // Its own words instead: h with the case's meaning, and no iteration counts
  // turned into zeros (the machine-independent chart is against cells).
  EXPECT_NE(text.find("h = 0.1 / N"), std::string::npos);
  EXPECT_NE(text.find("What a target costs: cells against RDE"), std::string::npos);
  EXPECT_EQ(text.find("cells × iterations against"), std::string::npos);
  EXPECT_EQ(text.find("in 0 "), std::string::npos);
  // grids.csv: a declared count of cells, not nx = cells, ny = nz = 1; the
  // case's own columns (case, quantity, levels: no particle-bed factors) and
  // the unknown iterations left empty.
  const std::string grids = test_support::slurp(dir / "grids.csv");
  const std::string row = grids.substr(grids.find('\n') + 1, grids.find('\n', grids.find('\n') + 1) - grids.find('\n') - 1);
  EXPECT_EQ(row.find(",6400,1,1,"), std::string::npos) << row;
  EXPECT_NE(row.find(",,,6400,converged,"), std::string::npos) << row;
  EXPECT_EQ(row.rfind("cavity mean_u2,cavity,mean_u2,{},", 0), 0u) << row;
  EXPECT_NE(row.find(",converged,"), std::string::npos);
  EXPECT_EQ(grids.substr(0, grids.find('\n')).find("drag"), std::string::npos) << grids.substr(0, 200);
}

TEST(ReportCaseWords, TheParticleBedReportKeepsItsWords) {
  const fs::path dir = test_support::fresh_scratch_dir("case_words", "physical");
  StudyReportData d = test::synthetic_study();
  d.export_charts = false;
  write_study_report(d, dir, test::fake_extrapolation);
  const std::string text = readable_text(dir);
  for (const char* w : {"Δ*", "particle", "drag", "FM18", "DP*", "outer iteration"})
    EXPECT_NE(text.find(w), std::string::npos) << w;
}

}  // namespace
}  // namespace gridfree
