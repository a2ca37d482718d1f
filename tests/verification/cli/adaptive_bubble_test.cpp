// SPDX-License-Identifier: GPL-3.0-or-later
// An adaptive series on a real, small bursting bubble (the fictitious
// bubble of docs/PHYSICS.md §6 in a 20 × 60 × 10 dp domain, the smallest the
// generator allows with the freeboard cut at 60; each job a few seconds)
// against the fixed series on the same ladder Δ* = 2/1.25^k, k = 0..5,
// computed in the same test with the real worker:
//
//  - the adaptive series (target 1 %) ends target_met with fewer grids than
//    the ladder, and records the compute it did not spend;
//  - it stopped at the first grid that meets the rule: `gridfree extrapolate`
//    on every shorter prefix (≥ 4 grids) of the fixed series' dp* — the same
//    jobs, so the same numbers — gives a verdict other than converged or an
//    RDE above the target, and on the adaptive series' own grids it meets it;
//  - its f0 equals the fixed series' f0 within the larger of their U.
//
// And a ladder started too coarse, Δ* = 3.3/1.25^k: the fit of all its grids
// stays pre-asymptotic (the coarsest rung lies outside the asymptotic range),
// the fit window of the finest grids (sched/adaptive_window.h) stops it, and
// its f0 equals the fixed Δ* 2 series' f0 within the larger U.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "project_paths.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::kGridfreeExe;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::sqlite_query;
constexpr double kTarget = 0.01;

gridfree::test_support::CommandRun gridfree_in(const fs::path& dir, const std::string& args) {
  return gridfree::test_support::run_command("cd '" + dir.string() + "' && '" + kGridfreeExe.string() + "' " + args,
                                             dir / "stderr.txt");
}

void write_study(const fs::path& dir, const std::string& name, const nlohmann::json& grids) {
  auto doc = quickstart_document();
  doc["name"] = name;
  auto c = doc["cases"]["PC1"];
  c["domain_dp"] = {20, 60, 10};
  c["probes"]["pressure_drop"] = {{"y1_dp", 4}, {"y2_dp", 54}};
  doc["cases"] = {{"small", c}};
  doc.erase("factors");
  doc.erase("design");
  doc["grids"] = grids;
  std::ofstream(dir / (name + ".json")) << doc.dump(2);
}

// (h, f) of a database's only series, coarse to fine.
std::vector<std::pair<double, double>> series_of(const fs::path& db) {
  std::stringstream rows(sqlite_query(db, "SELECT delta_star, dp_star FROM v_results ORDER BY delta_star DESC"));
  std::vector<std::pair<double, double>> out;
  double h = 0, f = 0;
  char bar = 0;
  while (rows >> h >> bar >> f) out.emplace_back(h, f);
  return out;
}

// `gridfree extrapolate` on the first n points: verdict and the finest grid's RDE.
std::pair<std::string, double> extrapolate_prefix(const fs::path& dir, const std::vector<std::pair<double, double>>& s,
                                                  std::size_t n) {
  nlohmann::json in = {{"h", nlohmann::json::array()}, {"f", nlohmann::json::array()}};
  for (std::size_t k = 0; k < n; ++k) {
    in["h"].push_back(s[k].first);
    in["f"].push_back(s[k].second);
  }
  std::ofstream(dir / "prefix.json") << in.dump();
  const auto r = gridfree_in(dir, "extrapolate prefix.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto ex = nlohmann::json::parse(r.out);
  double rde = NAN, finest = INFINITY;
  for (const auto& g : ex["grids"])
    if (g["h"].get<double>() < finest) finest = g["h"].get<double>(), rde = g["rde"].get<double>();
  return {ex["verdict"]["value"].get<std::string>(), rde};
}

TEST(AdaptiveBubble, StopsAtTheFirstGridMeetingTheTargetWithTheFixedSeriesF0) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_bubble_test", "bubble");
  std::vector<double> ladder;
  for (int k = 0; k <= 5; ++k) ladder.push_back(2.0 / std::pow(1.25, k));  // 2 → 0.655
  write_study(dir, "fixed", {{"delta_star", ladder}});
  write_study(dir, "adaptive", {{"target_rde", kTarget}, {"coarsest_delta_star", 2.0}, {"ratio", 1.25},
                                {"finest_delta_star", 0.6}});
  auto r = gridfree_in(dir, "run fixed.json -j 2 --db f.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = gridfree_in(dir, "run adaptive.json -j 2 --db a.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = dir / "a.sqlite", f = dir / "f.sqlite";

  ASSERT_EQ(sqlite_query(a, "SELECT adaptive_status, verdict FROM series"), "target_met|converged")
      << sqlite_query(a, "SELECT adaptive_note FROM series");
  const auto fixed = series_of(f), adaptive = series_of(a);
  ASSERT_EQ(fixed.size(), ladder.size());
  ASSERT_LT(adaptive.size(), fixed.size()) << "the target should be met before the finest rung";
  EXPECT_NE(sqlite_query(a, "SELECT adaptive_note FROM series").find("saved an estimated"), std::string::npos);
  // Same jobs, same numbers: the adaptive grids are the ladder's first ones.
  for (std::size_t k = 0; k < adaptive.size(); ++k) {
    EXPECT_NEAR(adaptive[k].first, fixed[k].first, 1e-12);
    EXPECT_DOUBLE_EQ(adaptive[k].second, fixed[k].second);
  }
  for (std::size_t n = 4; n < adaptive.size(); ++n) {
    const auto [verdict, rde] = extrapolate_prefix(dir, fixed, n);
    EXPECT_TRUE(verdict != "converged" || rde > kTarget) << n << " grids: " << verdict << ", RDE " << rde;
  }
  const auto [verdict, rde] = extrapolate_prefix(dir, fixed, adaptive.size());
  EXPECT_EQ(verdict, "converged");
  EXPECT_LE(rde, kTarget);

  const double f0_a = std::stod(sqlite_query(a, "SELECT f0 FROM v_series")),
               u_a = std::stod(sqlite_query(a, "SELECT finest_u FROM v_series"));
  const double f0_f = std::stod(sqlite_query(f, "SELECT f0 FROM v_series")),
               u_f = std::stod(sqlite_query(f, "SELECT finest_u FROM v_series"));
  EXPECT_LE(std::abs(f0_a - f0_f), std::max(u_a, u_f)) << "adaptive " << f0_a << " ± " << u_a << ", fixed " << f0_f
                                                       << " ± " << u_f;
}

TEST(AdaptiveBubble, ALadderStartedTooCoarseStopsOnTheWindowOfItsFinestGrids) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_bubble_test", "coarse_start");
  std::vector<double> ladder;
  for (int k = 0; k <= 5; ++k) ladder.push_back(2.0 / std::pow(1.25, k));  // 2 → 0.655
  write_study(dir, "fixed", {{"delta_star", ladder}});
  write_study(dir, "adaptive", {{"target_rde", kTarget}, {"coarsest_delta_star", 3.3}, {"ratio", 1.25},
                                {"finest_delta_star", 0.5}});
  auto r = gridfree_in(dir, "run fixed.json -j 2 --db f.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = gridfree_in(dir, "run adaptive.json -j 2 --db a.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = dir / "a.sqlite", f = dir / "f.sqlite";
  const std::string note = sqlite_query(a, "SELECT adaptive_note FROM series");
  ASSERT_EQ(sqlite_query(a, "SELECT adaptive_status, verdict FROM series"), "target_met|converged") << note;
  EXPECT_NE(note.find("coarser one"), std::string::npos) << note;
  // Without the window it would not have stopped: all its grids together
  // are not converged.
  const auto adaptive = series_of(a);
  EXPECT_NE(extrapolate_prefix(dir, adaptive, adaptive.size()).first, "converged");
  // The report shows the fit the stop was decided on, not the all-grid one.
  std::ifstream md(dir / "reports/adaptive/report.md");
  std::stringstream report;
  report << md.rdbuf();
  EXPECT_NE(report.str().find("**converged**"), std::string::npos) << report.str().substr(0, 2000);
  EXPECT_EQ(report.str().find("**pre-asymptotic**"), std::string::npos);
  const double f0_a = std::stod(sqlite_query(a, "SELECT f0 FROM v_series")),
               u_a = std::stod(sqlite_query(a, "SELECT finest_u FROM v_series"));
  const double f0_f = std::stod(sqlite_query(f, "SELECT f0 FROM v_series")),
               u_f = std::stod(sqlite_query(f, "SELECT finest_u FROM v_series"));
  EXPECT_LE(std::abs(f0_a - f0_f), std::max(u_a, u_f)) << "adaptive " << f0_a << " ± " << u_a << ", fixed " << f0_f
                                                       << " ± " << u_f;
}

}  // namespace
