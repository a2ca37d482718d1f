// SPDX-License-Identifier: GPL-3.0-or-later
// The beds' structure end to end with the real worker: every job's result
// carries the summary of the bed it solved (docs/INTERFACE.md §2 "bed"), and
// the report's "About this case: bed structure" shows those numbers, one
// line for a single case and one for an ensemble (ranges over its
// instances). Three bursting-bubble beds (seeds 21–23) on three coarse grids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::run_executable;
using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;

std::string bed_text(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string bed_format(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The bed of case `name` as stored: every result of the case must hold the
// same one (the same particles), checked on its three grids.
nlohmann::json stored_bed(const fs::path& db, const std::string& name) {
  const std::string rows = sqlite_query(
      db, "SELECT json_extract(r.result_json, '$.bed') FROM v_results v JOIN results r ON r.job_id = v.job_id "
          "WHERE v.study = 'beds' AND v.case_name = '" + name + "' ORDER BY v.grid_index");
  std::istringstream in(rows);
  std::string first, line;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (n++ == 0) first = line;
    auto a = nlohmann::json::parse(line), b = nlohmann::json::parse(first);
    a.erase("cpu_s");
    b.erase("cpu_s");
    EXPECT_EQ(a, b) << name << ": the grids of one case saw different beds";
  }
  EXPECT_EQ(n, 3) << rows;
  return nlohmann::json::parse(first);
}

TEST(BedAboutCli, ReportShowsEachCasesBedFromItsResults) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("cli_test", "bed_about");
  auto study = quickstart_document();
  study["name"] = "beds";
  const auto pc1 = study["cases"]["PC1"];
  study["cases"] = nlohmann::json::object();
  for (int seed : {21, 22, 23}) {
    auto c = pc1;
    c["particles"]["generator"]["seed"] = seed;
    study["cases"]["s" + std::to_string(seed)] = c;
  }
  study["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  study["design"] = "factorial";
  study["ensembles"] = {{"snaps", {"s21", "s22"}}};
  study["grids"] = {{"delta_star", {5.0, 4.0, 3.3}}};
  const fs::path study_file = dir / "beds.json";
  std::ofstream(study_file) << study.dump(2);

  const auto run = run_executable("gridfree", "run " + shell_quote(study_file.string()) + " --db " +
                                                  shell_quote((dir / "b.sqlite").string()) + " -j 2 --out " +
                                                  shell_quote((dir / "report").string()),
                                  dir);
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  const fs::path db = dir / "b.sqlite";
  const nlohmann::json one = stored_bed(db, "s23");
  const nlohmann::json a = stored_bed(db, "s21"), b = stored_bed(db, "s22");
  // The bubble bed's 4649 particles (docs/PARTICLES.md), not ordered.
  EXPECT_EQ(one.at("particles"), 4649);
  EXPECT_FALSE(one.at("ordered").get<bool>());

  const std::string md = bed_text(dir / "report/report.md");
  const std::string html = bed_text(dir / "report/report.html");
  ASSERT_NE(md.find("## About this case: bed structure"), std::string::npos) << md.substr(0, 4000);
  EXPECT_NE(html.find("About this case: bed structure"), std::string::npos);
  // The single case's line, with its own numbers as stored.
  const std::string line = "s23: N 4649, ε_s " + bed_format("%.3f", one.at("solids_fraction").get<double>());
  EXPECT_NE(md.find(line), std::string::npos) << line << "\n" << md.substr(md.find("## About this case: bed"), 3000);
  for (const std::string& piece :
       {"in the core " + bed_format("%.2g", one.at("/largest_structure_factor_core/s_over_n"_json_pointer).get<double>()) +
            " (" + one.at("/largest_structure_factor_core/axis"_json_pointer).get<std::string>() + ", period " +
            bed_format("%.2f", one.at("/largest_structure_factor_core/period_dp"_json_pointer).get<double>()) + " d)",
        std::string("random (core peak < 0.05 N)"),
        "g(r) contact peak " + bed_format("%.2f", one.at("/rdf/contact_peak"_json_pointer).get<double>()),
        "local ε_s " + bed_format("%.3f", one.at("/local_solids_fraction/mean"_json_pointer).get<double>()) + " ± " +
            bed_format("%.3f", one.at("/local_solids_fraction/std"_json_pointer).get<double>())})
    EXPECT_NE(md.find(piece), std::string::npos) << piece;
  // The ensemble: one line, the range of the two instances' contact peaks.
  const double ga = a.at("/rdf/contact_peak"_json_pointer).get<double>(),
               gb = b.at("/rdf/contact_peak"_json_pointer).get<double>();
  const std::string lo = bed_format("%.2f", std::min(ga, gb)), hi = bed_format("%.2f", std::max(ga, gb));
  const std::string range = lo == hi ? lo : lo + " – " + hi;
  EXPECT_NE(md.find("ensemble snaps (2 instances): N 4649, "), std::string::npos);
  EXPECT_NE(md.find("random in every instance"), std::string::npos);
  EXPECT_NE(md.find("g(r) contact peak " + range + " at"), std::string::npos) << range;
  EXPECT_EQ(md.find("s21: N"), std::string::npos) << "an instance got a line of its own";
}

}  // namespace
