// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive series of an external study (docs/EXTERNAL.md "Adaptive
// series") with the poly test solver (tests/fixtures/external/poly:
// f(h) = 1 + 0.5 h², so f0 = 1 and the finest grid's RDE ≈ 1.25 · 0.5 h²).
// The ladder is in h = 1/N from N = 4 by ratio 1.25: h_k = 0.25 / 1.25^k,
// each rung's N the integer whose h is nearest to h_k in log. With a 0.5 %
// target the series must stop at N = 12 (RDE ≈ 0.43 %; N = 10 gives
// ≈ 0.63 %), having run exactly the ladder's N = 4, 5, 6, 8, 10, 12, each
// job's derived variable and h from that N, and recover f0 = 1. A study
// whose h is not monotone in N, one with two grid variables and one whose
// rungs round to the same N are refused naming the JSON path. `plan
// --target-rde` fits RDE(h) to the finished series and predicts the grids
// a tighter target needs; without one it says the RDE is unknown. h given
// as (V/cells)^(1/dim) gives the same rungs as 1/N; a real variable's rungs
// are rounded to 4 significant digits.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "project_paths.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;

const fs::path kPolyWorker = fs::path(GRIDFREE_BIN_DIR) / "gridfree-worker";

fs::path adaptive_poly_dir(const std::string& name, const nlohmann::json& grids, const std::string& h = "1 / N") {
  const auto dir = gridfree::test_support::fresh_scratch_dir("external_adaptive_cli_test", name);
  fs::copy(gridfree::test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
           fs::copy_options::recursive);
  auto doc = nlohmann::json::parse(R"({"schema": "gridfree/study/1", "name": "poly_adaptive",
    "cases": {"poly": {"external": {
      "template": "poly", "render": ["input.txt"],
      "variables": {"h_cell": "1 / N"}, "cells": "N ^ 2",
      "command": ["sh", "solve.sh"], "version": "poly 1",
      "collect": {"quantities": {
        "f": {"units": "J", "description": "the test function", "file": "out.dat", "column": 1}}}}}}})");
  doc["cases"]["poly"]["external"]["h"] = h;
  doc["grids"] = grids;
  // The stops and RDE below are worked by hand for the capped fit (U = 1.25|f0 − f|);
  // the default, averaged, also holds the first-order fit's f0 and needs more grids.
  doc["extrapolation"] = {{"method", "capped"}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  return dir;
}

nlohmann::json ladder_grids() {
  return nlohmann::json::parse(
      R"({"target_rde": 0.005, "ratio": 1.25, "variables": {"N": {"coarsest": 4, "finest": 64}}})");
}

CommandRun run_poly(const fs::path& dir, const std::string& args) {
  return gridfree_in(dir, args, "GRIDFREE_WORKER=" + shell_quote(kPolyWorker.string()));
}

// The integer N whose h = 1/N is nearest in log to the ladder's h_k.
int expected_n(int k) {
  const double wanted = 0.25 / std::pow(1.25, k);
  const double x = 1 / wanted;
  const double a = std::floor(x), b = std::ceil(x);
  return static_cast<int>(std::fabs(std::log(b * wanted)) < std::fabs(std::log(a * wanted)) ? b : a);
}

TEST(ExternalAdaptiveCli, StopsAtTheTargetWithTheGridsTheInversionOfHChooses) {
  const auto dir = adaptive_poly_dir("stop", ladder_grids());
  const CommandRun r = run_poly(dir, "run study.json -j 2 --db g.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT adaptive_status, verdict FROM series"), "target_met|converged");

  // The grids run, coarse to fine: the ladder's N for k = 0 .. 5.
  const std::string ns = sqlite_query(
      db, "SELECT group_concat(n, ',') FROM (SELECT CAST(json_extract(j.spec_json, '$.case.external.variables.N') AS INTEGER) AS n "
          "FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id ORDER BY sj.grid_index)");
  std::string want;
  for (int k = 0; k <= 5; ++k) want += (k ? "," : "") + std::to_string(expected_n(k));
  EXPECT_EQ(want, "4,5,6,8,10,12");  // the inversion, worked by hand
  EXPECT_EQ(ns, want);
  // Each job's derived variable and h follow from its N; the nominal h is the ladder's.
  const std::string mismatches = sqlite_query(
      db, "SELECT COUNT(*) FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id WHERE "
          "abs(json_extract(j.spec_json, '$.case.external.variables.h_cell') * "
          "    json_extract(j.spec_json, '$.case.external.variables.N') - 1) > 1e-12 "
          "OR abs(json_extract(j.spec_json, '$.numerics.grid.h') * json_extract(j.spec_json, '$.case.external.variables.N') - 1) > 1e-12 "
          "OR abs(j.delta_star * json_extract(j.spec_json, '$.case.external.variables.N') - 1) > 1e-12 "
          "OR abs(sj.delta_star_nominal - 0.25 / pow(1.25, sj.grid_index)) > 1e-12");
  EXPECT_EQ(mismatches, "0");
  // f = 1 + 0.5 h² exactly: f0 = 1 to round-off (17 digits written).
  const double f0 = std::stod(sqlite_query(db, "SELECT f0 FROM extrapolations WHERE chosen = 1"));
  EXPECT_NEAR(f0, 1.0, 1e-9);
  // Every decision logged; the stop names h and the grids it did not run.
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive'"), "3");
  const std::string stop = sqlite_query(db, "SELECT message FROM events WHERE kind = 'adaptive' ORDER BY id DESC LIMIT 1");
  EXPECT_NE(stop.find("stopped at h 0.0833"), std::string::npos) << stop;
  const std::string refine = sqlite_query(db, "SELECT message FROM events WHERE kind = 'adaptive' ORDER BY id LIMIT 1");
  EXPECT_NE(refine.find("next grid h 0.102 (N = 10, 100 cells"), std::string::npos) << refine;

  // plan --target-rde 0.1 %: RDE(h) fitted to this series' grids is
  // 1.25 · 0.5 h² = 0.625 h² exactly (f0 = 1); N = 24 predicts 0.109 %,
  // N = 30 (the 10th rung) 0.069 %: 10 grids needed, costs from the history.
  CommandRun plan = run_poly(dir, "plan study.json --target-rde 0.001 --json --db g.sqlite");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const auto t = nlohmann::json::parse(plan.out)["target"]["series"][0];
  EXPECT_EQ(t["series"], "poly f");
  EXPECT_NEAR(t["model"]["p"].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(t["model"]["a"].get<double>(), 0.625, 1e-6);
  EXPECT_TRUE(t["reachable"].get<bool>());
  EXPECT_EQ(t["grids_needed"], 10);
  EXPECT_EQ(t["grids"][9]["variables"]["N"], 30.0);
  EXPECT_TRUE(t["grids"][9]["needed"].get<bool>());
  EXPECT_FALSE(t["grids"][10]["needed"].get<bool>());
  EXPECT_TRUE(t["cpu_s"].is_number());
  // Without a finished series the RDE is unknown, not invented.
  plan = run_poly(dir, "plan study.json --target-rde 0.001 --json --db none.sqlite");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const auto u = nlohmann::json::parse(plan.out)["target"]["series"][0];
  EXPECT_TRUE(u["model"].is_null());
  EXPECT_NE(u["basis"].get<std::string>().find("RDE unknown"), std::string::npos);
  EXPECT_FALSE(u["grids"][0]["needed"].get<bool>());
  EXPECT_TRUE(u["grids"][0]["predicted_rde"].is_null());

  // A second run adds nothing.
  const CommandRun again = run_poly(dir, "run study.json -j 2 --db g.sqlite");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM study_jobs"), "6");
}

TEST(ExternalAdaptiveCli, TheVolumeOverCellsFormInvertsThroughTheCellsExpression) {
  // h = (1 / N²)^(1/2) = 1/N written as {"cells", "volume", "dim"}: the same
  // rungs as "1 / N", listed by plan at the study's own target.
  auto dir = adaptive_poly_dir("volume", ladder_grids());
  auto doc = nlohmann::json::parse(std::ifstream(dir / "study.json"));
  doc["cases"]["poly"]["external"]["h"] = {{"cells", "N * N"}, {"volume", 1}, {"dim", 2}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  const CommandRun plan = run_poly(dir, "plan study.json --json --db none.sqlite");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const auto grids = nlohmann::json::parse(plan.out)["target"]["series"][0]["grids"];
  ASSERT_GE(grids.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(grids[k]["variables"]["N"].get<double>(), expected_n(k)) << k;
    EXPECT_NEAR(grids[k]["h"].get<double>() * expected_n(k), 1.0, 1e-12) << k;
  }
}

TEST(ExternalAdaptiveCli, ARealVariableIsRoundedToFourSignificantDigits) {
  // A scale factor s with h = 1 / (4 s): the rungs are s = 1.25^k to 4
  // significant digits (1.953 for 1.953125), h recomputed from them.
  auto grids = ladder_grids();
  grids["variables"] = {{"s", {{"coarsest", 1}, {"finest", 16}, {"type", "real"}}}};
  auto dir = adaptive_poly_dir("real", grids, "1 / (4 * s)");
  auto doc = nlohmann::json::parse(std::ifstream(dir / "study.json"));
  doc["cases"]["poly"]["external"]["variables"] = {{"h_cell", "1 / (4 * s)"}, {"N", "round(4 * s)"}};
  doc["cases"]["poly"]["external"]["cells"] = "16 * s ^ 2";
  std::ofstream(dir / "study.json") << doc.dump(2);
  const CommandRun plan = run_poly(dir, "plan study.json --json --db none.sqlite");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const auto rungs = nlohmann::json::parse(plan.out)["target"]["series"][0]["grids"];
  const double want[] = {1, 1.25, 1.563, 1.953, 2.441, 3.052};
  ASSERT_GE(rungs.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(rungs[k]["variables"]["s"].get<double>(), want[k]) << k;
    EXPECT_NEAR(rungs[k]["h"].get<double>() * 4 * want[k], 1.0, 1e-12) << k;
  }
}

TEST(ExternalAdaptiveCli, RefusesHNotMonotoneTwoGridVariablesAndRungsRoundingToOneValue) {
  // h = 1/N + 0.001 N² falls to N ≈ 8 and rises after.
  auto dir = adaptive_poly_dir("monotone", ladder_grids(), "1 / N + 0.001 * N ^ 2");
  CommandRun r = run_poly(dir, "validate study.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/cases/poly/external/h: h = 1 / N + 0.001 * N ^ 2 increases from"), std::string::npos) << r.err;

  auto two = ladder_grids();
  two["variables"]["M"] = {{"coarsest", 2}, {"finest", 32}};
  dir = adaptive_poly_dir("two", two);
  r = run_poly(dir, "validate study.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/grids/variables: an adaptive series refines one grid variable"), std::string::npos) << r.err;

  auto close = ladder_grids();
  close["ratio"] = 1.1;  // h 0.25 → 0.227: N = 4.4 rounds to 4 again
  dir = adaptive_poly_dir("close", close);
  r = run_poly(dir, "validate study.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/grids/ratio: ladder rungs 1 and 2 of case poly"), std::string::npos) << r.err;
}

}  // namespace
