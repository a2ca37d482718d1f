// SPDX-License-Identifier: GPL-3.0-or-later
// Ensembles end to end with the fake worker (tests/fixtures/fake_worker.sh,
// whose case okplusK gives dp* = 1159 + K + Δ*, so f0 = 1159 + K): three
// instances K = 0, 2, 7 under two drag laws and one case outside the
// ensemble. Checked: the ensembles table, v_ensemble_budget against the
// statistics computed here from the per-series rows of v_series and
// v_results, the analytic ensemble mean 1162 and sd sqrt(13), and the
// report's Ensembles section and CSV files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::kFakeWorker;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::shell_quote;

std::string capture(const std::string& cmd, int* code = nullptr) {
  std::string out;
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
  const int status = pclose(p);
  if (code) *code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

// Rows of a query, '|'-separated columns.
std::vector<std::vector<std::string>> rows(const fs::path& db, const std::string& query) {
  std::istringstream in(capture("sqlite3 " + shell_quote(db.string()) + " " + shell_quote(query)));
  std::vector<std::vector<std::string>> out;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cols;
    std::string col;
    std::istringstream l(line);
    while (std::getline(l, col, '|')) cols.push_back(col);
    if (!line.empty() && line.back() == '|') cols.push_back("");
    out.push_back(cols);
  }
  return out;
}

struct Stats {
  double mean = 0, sd = 0;
};

// Mean and sample sd, written out here independently of the report and SQL.
Stats stats(const std::vector<double>& x) {
  Stats s;
  for (double v : x) s.mean += v / static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(ss / static_cast<double>(x.size() - 1));
  return s;
}

fs::path write_ensembles_study(const fs::path& dir) {
  auto doc = quickstart_document();
  doc["name"] = "ens";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = nlohmann::json::object();
  for (const char* c : {"okplus0", "okplus2", "okplus7", "ok"}) doc["cases"][c] = pc1;
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk", "hkl"}}};
  doc["design"] = "factorial";
  doc["ensembles"] = {{"snap", {"okplus0", "okplus2", "okplus7"}}};
  doc["grids"] = {{"delta_star", {5.0, 4.0, 3.3, 2.5}}};
  const auto file = dir / "ens.json";
  std::ofstream(file) << doc.dump(2);
  return file;
}

TEST(EnsemblesCli, ViewAndReportGiveTheEnsembleStatistics) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("cli_test", "ensembles");
  const auto study = write_ensembles_study(dir);
  int code = -1;
  const std::string log =
      capture("cd " + shell_quote(dir.string()) + " && GRIDFREE_WORKER=" + shell_quote(kFakeWorker.string()) + " " +
                  shell_quote(kGridfreeExe.string()) + " run " + shell_quote(study.string()) +
                  " --db ens.sqlite -j 2 --out report",
              &code);
  ASSERT_EQ(code, 0) << log;
  const auto db = dir / "ens.sqlite";
  EXPECT_EQ(rows(db, "SELECT name, case_name FROM ensembles ORDER BY case_name").size(), 3u);

  const auto view = rows(db,
                         "SELECT drag, instances, instances_converged, instances_with_f0, f0_mean, f0_sd, f0_sem, "
                         "f0_min, f0_max, grid_index, rde_mean, u_mean FROM v_ensemble_budget "
                         "WHERE study = 'ens' AND ensemble = 'snap' ORDER BY drag, grid_index");
  ASSERT_EQ(view.size(), 8u);  // 2 drag laws × 4 grids
  for (const auto& r : view) {
    ASSERT_EQ(r.size(), 12u);
    const std::string drag = r[0];
    EXPECT_EQ(r[1], "3");
    EXPECT_EQ(r[3], "3");
    // Independent: the three instances' f0 from v_series.
    std::vector<double> f0;
    for (const auto& s : rows(db, "SELECT f0 FROM v_series WHERE study = 'ens' AND drag = '" + drag +
                                      "' AND case_name LIKE 'okplus%'"))
      f0.push_back(std::stod(s[0]));
    ASSERT_EQ(f0.size(), 3u);
    const Stats st = stats(f0);
    const double mean = std::stod(r[4]), sd = std::stod(r[5]);
    // Same numbers through SQL and C++: agree to rounding (1e-9 relative).
    EXPECT_NEAR(mean, st.mean, 1e-9 * st.mean);
    EXPECT_NEAR(sd, st.sd, 1e-9 * st.sd);
    EXPECT_NEAR(std::stod(r[6]), st.sd / std::sqrt(3.0), 1e-9 * st.sd);
    // Analytic: f0 = 1159 + K exactly for dp* linear in Δ*; the fits
    // reproduce it to their solver tolerance (1e-6 relative is generous).
    EXPECT_NEAR(mean, 1162.0, 1162.0 * 1e-6);
    EXPECT_NEAR(sd, std::sqrt(13.0), 1e-3);
    EXPECT_NEAR(std::stod(r[7]), 1159.0, 1e-3);
    EXPECT_NEAR(std::stod(r[8]), 1166.0, 1e-3);
    // Mean RDE at this grid from the per-job rows of v_results.
    std::vector<double> rde;
    for (const auto& s : rows(db, "SELECT rde FROM v_results WHERE study = 'ens' AND drag = '" + drag +
                                      "' AND case_name LIKE 'okplus%' AND grid_index = " + r[9] +
                                      " AND rde IS NOT NULL"))
      rde.push_back(std::stod(s[0]));
    if (rde.empty()) {
      EXPECT_EQ(r[10], "");
    } else {
      EXPECT_NEAR(std::stod(r[10]), stats(rde).mean, 1e-9 * stats(rde).mean + 1e-15);
    }
  }

  // The report: section, CSV with the same mean, budget chart.
  std::ifstream md_in(dir / "report/report.md");
  const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("## Ensembles and uncertainty budget"), std::string::npos);
  EXPECT_NE(md.find("budget_snap.svg"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "report/budget_snap.svg"));
  EXPECT_TRUE(fs::exists(dir / "report/budget.csv"));
  std::ifstream csv(dir / "report/ensembles.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("ensemble,configuration,instances,converged,with_f0,f0_mean,f0_sd", 0), 0u) << header;
  int n = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> cols;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, ',');) cols.push_back(c);
    ASSERT_GE(cols.size(), 7u) << line;
    EXPECT_EQ(cols[0], "snap");
    EXPECT_NEAR(std::stod(cols[5]), std::stod(view[0][4]), 1e-9 * 1162);
    EXPECT_NEAR(std::stod(cols[6]), std::stod(view[0][5]), 1e-9 * 4);
    ++n;
  }
  EXPECT_EQ(n, 2);
}

}  // namespace
