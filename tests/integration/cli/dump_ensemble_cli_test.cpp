// SPDX-License-Identifier: GPL-3.0-or-later
// An ensemble of frozen snapshots read from one LAMMPS dump, run end to end
// by the real worker: the way a user verifies a transient run at several
// instants (docs/PARTICLES.md). Three held-out bubble configurations (seeds
// 11–13, used nowhere else) are generated, written to CSV by
// `gridfree-worker particles` and copied token for token into a three-step
// dump, so the dump route and the CSV route hold the same doubles: the first
// snapshot must give the CSV case's dp* to the last bit on every grid. The
// ensemble view's mean and sample sd are checked against the instances' f0
// from v_series, computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::run_executable;
using gridfree::test_support::shell_quote;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::sqlite_query;

nlohmann::json quickstart_case() { return quickstart_document()["cases"]["PC1"]; }

// The CSV's data rows as their text tokens (header `x,y,z,d`).
std::vector<std::vector<std::string>> csv_rows(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("x,y,z,d", 0), 0u) << line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cols;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, ',');) cols.push_back(c);
    rows.push_back(cols);
  }
  return rows;
}

// Generates seed `seed` of the bubble case as CSV.
fs::path generate(const fs::path& dir, int seed) {
  auto c = quickstart_case();
  nlohmann::json spec = {{"domain_dp", c["domain_dp"]},
                         {"particle_diameter_cm", c["particle_diameter_cm"]},
                         {"boundaries", c["boundaries"]},
                         {"generator", {{"kind", "bursting_bubble"}, {"seed", seed}}}};
  const fs::path spec_file = dir / ("spec" + std::to_string(seed) + ".json");
  std::ofstream(spec_file) << spec.dump(2);
  const fs::path csv = dir / ("seed" + std::to_string(seed) + ".csv");
  const auto r = run_executable("gridfree-worker", "particles " + shell_quote(spec_file.string()) + " -o " +
                                                       shell_quote(csv.string()), dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return csv;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(std::stod(line));
  return out;
}

TEST(DumpEnsembleCli, SnapshotsOfOneDumpAreAnEnsembleAndMatchTheirCsv) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("cli_test", "dump_ensemble");
  auto c = quickstart_case();
  const double d_cm = c["particle_diameter_cm"].get<double>();  // domain_dp × d = the box in cm
  const std::vector<int> seeds = {11, 12, 13};
  std::vector<fs::path> csvs;
  for (int s : seeds) csvs.push_back(generate(dir, s));

  // One dump, timesteps 1000, 2000, 3000, in cgs with the box at the origin
  // and the columns in another order than the CSV's.
  {
    std::ofstream dump(dir / "bed.dump");
    for (std::size_t k = 0; k < csvs.size(); ++k) {
      const auto rows = csv_rows(csvs[k]);
      ASSERT_GT(rows.size(), 1000u);
      dump << "ITEM: TIMESTEP\n" << 1000 * (k + 1) << "\nITEM: NUMBER OF ATOMS\n" << rows.size()
           << "\nITEM: BOX BOUNDS pp ff pp\n";
      for (int a = 0; a < 3; ++a) dump << "0 " << c["domain_dp"][a].get<double>() * d_cm << "\n";
      dump << "ITEM: ATOMS id type diameter z y x\n";
      for (std::size_t i = 0; i < rows.size(); ++i)
        dump << i + 1 << " 1 " << rows[i][3] << " " << rows[i][2] << " " << rows[i][1] << " " << rows[i][0] << "\n";
    }
  }

  auto study = quickstart_document();
  study["name"] = "dump-ensemble";
  study["cases"] = nlohmann::json::object();
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    auto snap = c;
    snap["particles"] = {{"file", "bed.dump"}, {"format", "lammps"}, {"units", "cgs"}, {"timestep", 1000 * (k + 1)}};
    study["cases"]["snap" + std::to_string(k + 1)] = snap;
  }
  auto from_csv = c;
  from_csv["particles"] = {{"file", csvs[0].filename().string()}, {"format", "csv"}};
  study["cases"]["csv1"] = from_csv;
  study["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  study["design"] = "factorial";
  study["ensembles"] = {{"dump", {"snap1", "snap2", "snap3"}}};
  study["grids"] = {{"delta_star", {3.3, 2.8, 2.4, 2.0, 1.7}}};
  const fs::path study_file = dir / "study.json";
  std::ofstream(study_file) << study.dump(2);

  const auto run = run_executable("gridfree", "run " + shell_quote(study_file.string()) + " --db " +
                                                  shell_quote((dir / "d.sqlite").string()) + " -j 2 --out " +
                                                  shell_quote((dir / "report").string()),
                                  dir);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const fs::path db = dir / "d.sqlite";

  // The first snapshot and its CSV: the same particles, the same answer.
  const auto snap1 = numbers(sqlite_query(
      db, "SELECT printf('%.17g', dp_star) FROM v_results WHERE study = 'dump-ensemble' AND case_name = 'snap1' "
          "ORDER BY grid_index"));
  const auto csv1 = numbers(sqlite_query(
      db, "SELECT printf('%.17g', dp_star) FROM v_results WHERE study = 'dump-ensemble' AND case_name = 'csv1' "
          "ORDER BY grid_index"));
  ASSERT_EQ(snap1.size(), 5u);
  ASSERT_EQ(csv1.size(), 5u);
  for (std::size_t g = 0; g < snap1.size(); ++g) EXPECT_EQ(snap1[g], csv1[g]) << "grid " << g;

  // The instances are different beds: their f0 differ.
  const auto f0 = numbers(sqlite_query(
      db, "SELECT printf('%.17g', f0) FROM v_series WHERE study = 'dump-ensemble' AND case_name LIKE 'snap%'"));
  ASSERT_EQ(f0.size(), 3u);
  double mean = 0;
  for (double v : f0) mean += v / 3.0;
  double ss = 0;
  for (double v : f0) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / 2.0);
  EXPECT_GT(sd, 1e-4 * mean);

  const auto view = numbers(sqlite_query(
      db, "SELECT printf('%.17g', f0_mean) || char(10) || printf('%.17g', f0_sd) FROM v_ensemble_budget "
          "WHERE study = 'dump-ensemble' AND ensemble = 'dump' AND grid_index = 0"));
  ASSERT_EQ(view.size(), 2u);
  EXPECT_NEAR(view[0], mean, 1e-12 * mean);
  EXPECT_NEAR(view[1], sd, 1e-9 * sd);
  EXPECT_TRUE(fs::exists(dir / "report/budget_dump.svg"));
}

}  // namespace
