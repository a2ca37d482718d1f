// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run` of a study with the alignment check, with the fake worker
// (tests/fixtures/fake_worker.sh: dp* = 1159 + Δ* of the job's cells): the
// variants run as jobs, the series is extrapolated from its own grids only,
// v_alignment and the report's alignment.csv give the spread computed here
// from the cells; the same study without the option has no variants and no
// alignment section.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::sqlite_query;

fs::path write_alignment_study(const fs::path& dir, const std::string& name, bool alignment) {
  auto doc = quickstart_document();
  doc["name"] = name;
  doc["cases"] = {{"ok", doc["cases"]["PC1"]}};
  doc.erase("factors");
  doc.erase("design");
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.5}}};
  if (alignment) doc["alignment"] = {{"delta_star", {3.3, 2.5}}, {"ny_offsets", {1, 2}}};
  const auto path = dir / (name + ".json");
  std::ofstream(path) << doc.dump(2);
  return path;
}

// The fake worker's dp* on a grid of the quickstart domain (30 × 200 × 10 dp).
double fake_dp(int nx, int ny, int nz) { return 1159.0 + std::cbrt(30.0 * 200.0 * 10.0 / (double(nx) * ny * nz)); }

TEST(StudyAlignmentCli, VariantsRunAndTheSpreadReachesViewAndReport) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("alignment_cli_test", "with");
  write_alignment_study(dir, "aligned", true);
  const CommandRun run = gridfree_in(dir, "run aligned.json -j 2 --db g.sqlite");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE status = 'done'"), "8");  // 4 grids + 2 × 2 variants
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM v_results"), "4");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM uncertainties"), "4");  // the extrapolation saw the 4 grids only
  const std::string rows = sqlite_query(db, "SELECT nx, ny, nz, spread FROM v_alignment ORDER BY grid_index");
  std::istringstream lines(rows);
  std::string report;
  {
    std::ifstream f(dir / "reports/aligned/alignment.csv");
    ASSERT_TRUE(f.good()) << "no alignment.csv";
    std::stringstream ss;
    ss << f.rdbuf();
    report = ss.str();
  }
  int checked = 0;
  for (std::string line; std::getline(lines, line); ++checked) {
    int nx = 0, ny = 0, nz = 0;
    double spread = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d|%d|%d|%lf", &nx, &ny, &nz, &spread), 4) << line;
    const double v[] = {fake_dp(nx, ny, nz), fake_dp(nx, ny + 1, nz), fake_dp(nx, ny + 2, nz)};
    const double hi = *std::max_element(v, v + 3), lo = *std::min_element(v, v + 3);
    const double expected = (hi - lo) / ((v[0] + v[1] + v[2]) / 3);
    // The fake worker writes dp* with 12 significant digits: each value is off
    // by up to 0.5e-8 (dp* ≈ 1160), so the range by 1e-8 and the spread by 1e-8/1160 < 1e-11.
    EXPECT_NEAR(spread, expected, 1e-11) << line;
    // The report's CSV carries the same spread (full precision).
    bool found = false;
    std::istringstream csv(report);
    for (std::string row; std::getline(csv, row);) {
      if (row.find(std::to_string(nx) + "×" + std::to_string(ny) + "×" + std::to_string(nz)) == std::string::npos) continue;
      found = true;
      std::vector<std::string> cells;
      std::stringstream rs(row);
      for (std::string c; std::getline(rs, c, ',');) cells.push_back(c);
      ASSERT_GE(cells.size(), 8u) << row;
      EXPECT_NEAR(std::stod(cells[7]), expected, 1e-11) << row;
      EXPECT_NEAR(std::stod(cells[7]), spread, 1e-15) << row;  // the same stored values, the same rule
    }
    EXPECT_TRUE(found) << report;
  }
  EXPECT_EQ(checked, 2);
  std::ifstream md(dir / "reports/aligned/report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("## Alignment check"), std::string::npos);
}

TEST(StudyAlignmentCli, WithoutTheOptionNothingChanges) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("alignment_cli_test", "without");
  write_alignment_study(dir, "plain", false);
  const CommandRun run = gridfree_in(dir, "run plain.json -j 2 --db g.sqlite");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs"), "4");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM v_alignment"), "0");
  EXPECT_FALSE(fs::exists(dir / "reports/plain/alignment.csv"));
  std::ifstream md(dir / "reports/plain/report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_EQ(text.str().find("Alignment check"), std::string::npos);
}

}  // namespace
