// SPDX-License-Identifier: GPL-3.0-or-later
// Adaptive grid series end to end with the fake worker (tests/fixtures/
// fake_worker.sh: dp* = 1159 + Δ*, so f0 = 1159 exactly): a series runs
// coarse to fine and stops at the first grid whose RDE meets the target,
// with the f0 of the fixed series on the whole ladder; every decision is an
// event and in the report; a rerun adds nothing; a run killed with -9 and
// resumed by the daemon makes the same decisions without duplicates; a
// memory cap ends the series target_not_reached; `validate` judges the
// whole ladder and warns about a start above Δ* 2; `plan --target-rde` is
// a-priori without a database and fitted to the finished series with one.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::spawn_gridfree_in;
using gridfree::test_support::sqlite_int;
using gridfree::test_support::sqlite_query;
using gridfree::test_support::wait_until;

// One series ("ok": the fake worker converges) with the given grids.
fs::path write_series_study(const fs::path& dir, const std::string& name, const nlohmann::json& grids) {
  auto doc = quickstart_document();
  doc["name"] = name;
  doc["cases"] = {{"ok", doc["cases"]["PC1"]}};
  doc.erase("factors");
  doc.erase("design");
  doc["grids"] = grids;
  const auto path = dir / (name + ".json");
  std::ofstream(path) << doc.dump(2);
  return path;
}

// RDE ≈ 1.1e-3·Δ* for the fake's series: 0.1 % is met after a few rungs.
nlohmann::json adaptive_grids(const nlohmann::json& extra = nlohmann::json::object()) {
  nlohmann::json g = {{"target_rde", 0.001}, {"coarsest_delta_star", 3.3}, {"ratio", 1.25}, {"finest_delta_star", 0.5}};
  g.merge_patch(extra);
  return g;
}

// 3.3/1.25^k, k = 0..8: the fixed series over the whole ladder.
std::vector<double> whole_ladder() {
  std::vector<double> out;
  for (int k = 0; k <= 8; ++k) out.push_back(3.3 / std::pow(1.25, k));
  return out;
}

TEST(AdaptiveCli, StopsAtTheFirstGridMeetingTheTargetWithTheFixedSeriesF0) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "stop");
  write_series_study(dir, "adaptive", adaptive_grids());
  write_series_study(dir, "fixed", {{"delta_star", whole_ladder()}});
  auto r = gridfree_in(dir, "run adaptive.json -j 2 --db a.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = gridfree_in(dir, "run fixed.json -j 2 --db f.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = dir / "a.sqlite", f = dir / "f.sqlite";

  EXPECT_EQ(sqlite_query(a, "SELECT adaptive_status, verdict FROM series"), "target_met|converged");
  // The stop is at the first grid meeting the target: every grid before the
  // finest was checked and missed it (the RDE logged with each refining).
  const int grids = sqlite_int(a, "SELECT COUNT(*) FROM study_jobs");
  EXPECT_GT(grids, 4);
  EXPECT_LT(grids, 9);
  EXPECT_EQ(sqlite_int(a, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive' AND message LIKE '%stopped at%'"), 1);
  EXPECT_EQ(sqlite_int(a, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive'"), grids - 4 + 1);
  EXPECT_EQ(sqlite_int(a, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive' AND message LIKE '%RDE%> 0.1 %%'"),
            grids - 4 - 1);  // the first decision after 4 grids had no converged verdict yet (exact data)
  EXPECT_EQ(sqlite_query(a, "SELECT finest_rde <= 0.001 FROM v_series"), "1");
  // Same f0 within its U (the fake's exact f0 is 1159).
  const double f0_a = std::stod(sqlite_query(a, "SELECT f0 FROM v_series")),
               u_a = std::stod(sqlite_query(a, "SELECT finest_u FROM v_series"));
  const double f0_f = std::stod(sqlite_query(f, "SELECT f0 FROM v_series")),
               u_f = std::stod(sqlite_query(f, "SELECT finest_u FROM v_series"));
  EXPECT_LE(std::abs(f0_a - f0_f), std::max(u_a, u_f));
  EXPECT_NEAR(f0_a, 1159, u_a);
  // The saving is reported: in the stop note, the event and the report.
  EXPECT_NE(sqlite_query(a, "SELECT adaptive_note FROM series").find("saved an estimated"), std::string::npos);
  std::ifstream md(dir / "reports/adaptive/report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("## Adaptive grids"), std::string::npos);
  EXPECT_NE(text.str().find("stopped at Δ*"), std::string::npos) << text.str();

  // A rerun decides nothing again.
  r = gridfree_in(dir, "run adaptive.json -j 2 --db a.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(sqlite_int(a, "SELECT COUNT(*) FROM study_jobs"), grids);
  EXPECT_EQ(sqlite_int(a, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive'"), grids - 4 + 1);
}

TEST(AdaptiveCli, AKilledRunResumedByTheDaemonMakesTheSameDecisions) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "kill");
  write_series_study(dir, "adaptive", adaptive_grids());
  ASSERT_EQ(gridfree_in(dir, "run adaptive.json -j 2 --db once.sqlite").exit_code, 0);
  const auto once = dir / "once.sqlite", db = dir / "g.sqlite";
  // Killed (-9) once the first refinement was decided; the daemon resumes.
  pid_t pid = spawn_gridfree_in(dir, "run adaptive.json -j 2 --db g.sqlite", "0.3");
  ASSERT_TRUE(
      wait_until([&] { return sqlite_int(db, "SELECT COUNT(*) FROM events WHERE kind = 'adaptive'") >= 1; }, 60));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  pid = spawn_gridfree_in(dir, "daemon -j 2 --db g.sqlite", "0.05");
  ASSERT_TRUE(wait_until([&] { return sqlite_query(db, "SELECT status FROM studies") == "done"; }, 120));
  kill(pid, SIGTERM);
  waitpid(pid, &status, 0);
  const std::string decisions = "SELECT message FROM events WHERE kind = 'adaptive' ORDER BY id";
  EXPECT_EQ(sqlite_query(db, decisions), sqlite_query(once, decisions));
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT grid_index) FROM study_jobs"),
            sqlite_query(once, "SELECT COUNT(*), COUNT(DISTINCT grid_index) FROM study_jobs"));
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) = COUNT(DISTINCT job_id) FROM results"), "1");
  EXPECT_EQ(sqlite_query(db, "PRAGMA integrity_check"), "ok");
}

TEST(AdaptiveCli, AMemoryCapEndsTheSeriesTargetNotReached) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "cap");
  // The cap between the estimated memory of the fourth and the fifth rung,
  // as `plan` reports them (the memory model is the worker's).
  write_series_study(dir, "capped", adaptive_grids({{"target_rde", 0.0001}}));
  const auto p = gridfree_in(dir, "plan capped.json --json");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const auto grids = nlohmann::json::parse(p.out)["target"]["cases"][0]["grids"];
  const double fourth = grids[3]["memory_bytes"].get<double>(), fifth = grids[4]["memory_bytes"].get<double>();
  ASSERT_LT(fourth, fifth);
  const double cap = std::floor((fourth + fifth) / 2);
  write_series_study(dir, "capped", adaptive_grids({{"target_rde", 0.0001}, {"max_memory", cap}}));
  ASSERT_EQ(gridfree_in(dir, "run capped.json -j 2 --db g.sqlite").exit_code, 0);
  const auto db = dir / "g.sqlite";
  EXPECT_EQ(sqlite_query(db, "SELECT adaptive_status FROM series"), "target_not_reached");
  EXPECT_EQ(sqlite_int(db, "SELECT COUNT(*) FROM study_jobs"), 4);
  const std::string note = sqlite_query(db, "SELECT adaptive_note FROM series");
  EXPECT_NE(note.find("target not reached"), std::string::npos) << note;
  EXPECT_NE(note.find("> max_memory"), std::string::npos) << note;
  EXPECT_NE(note.find("best: Δ*"), std::string::npos) << note;
}

TEST(AdaptiveCli, BadAdaptiveFieldsAreRefusedWithTheirPath) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "bad");
  write_series_study(dir, "bad", adaptive_grids({{"ratio", 1.01}, {"max_memory", "much"}}));
  const auto r = gridfree_in(dir, "run bad.json --db g.sqlite");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/grids/ratio"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/grids/max_memory"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "g.sqlite"));
}

TEST(AdaptiveCli, ValidateJudgesTheWholeLadderAndWarnsAboutACoarseStart) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "warn");
  write_series_study(dir, "coarse", adaptive_grids());  // starts at Δ* 3.3
  write_series_study(dir, "fine", adaptive_grids({{"coarsest_delta_star", 2.0}}));
  auto r = gridfree_in(dir, "validate coarse.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("/grids/coarsest_delta_star 3.3 > 2"), std::string::npos) << r.err;
  r = gridfree_in(dir, "validate fine.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;  // not "4 grids leave 1 degree of freedom"
  EXPECT_NE(r.out.find("ok: 1 series, 4 jobs"), std::string::npos) << r.out;
}

TEST(AdaptiveCli, PlanTargetIsAPrioriWithoutDataAndFittedWithIt) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("adaptive_cli_test", "plan");
  write_series_study(dir, "fixed", {{"delta_star", whole_ladder()}});
  auto r = gridfree_in(dir, "plan fixed.json --target-rde 0.001 --json --db none.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto plan = nlohmann::json::parse(r.out)["target"];
  EXPECT_TRUE(plan["model"]["a_priori"].get<bool>());
  EXPECT_EQ(plan["cost_basis"], "costs from the a-priori cost model (study/cost_model.h)");
  EXPECT_EQ(nlohmann::json::parse(r.out)["series"][0]["cost_source"], "a-priori");  // docs/ORCHESTRATOR.md "Cost model"
  std::ofstream(dir / "garbage.sqlite") << "not a database";  // refused, named, left as it was
  const auto bad = gridfree_in(dir, "plan fixed.json --db garbage.sqlite");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--db"), std::string::npos) << bad.err;
  EXPECT_EQ(fs::file_size(dir / "garbage.sqlite"), std::string("not a database").size());
  EXPECT_DOUBLE_EQ(plan["model"]["p"].get<double>(), 1.0);
  EXPECT_FALSE(fs::exists(dir / "none.sqlite"));
  r = gridfree_in(dir, "plan fixed.json --target-rde 0.001");
  EXPECT_NE(r.out.find("a-priori"), std::string::npos) << r.out;

  ASSERT_EQ(gridfree_in(dir, "run fixed.json -j 2 --db g.sqlite").exit_code, 0);
  r = gridfree_in(dir, "plan fixed.json --target-rde 0.001 --json --db g.sqlite");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  plan = nlohmann::json::parse(r.out)["target"];
  EXPECT_FALSE(plan["model"]["a_priori"].get<bool>());
  // Every grid of the ladder ran: every grid is priced by its history, and
  // the header says so instead of naming the a-priori model.
  EXPECT_EQ(plan["cost_basis"].get<std::string>().rfind("costs of every grid from finished similar jobs", 0), 0u)
      << plan["cost_basis"];
  EXPECT_EQ(plan["cases"][0]["grids"][0]["cost_source"], "history");
  // The study's own finished jobs calibrate its time estimate: each grid's
  // ratio is the median of measured CPU / base model over the finished jobs
  // nearest in cell count, so it lies within their ratios' range.
  const auto row = nlohmann::json::parse(r.out)["series"][0];
  EXPECT_EQ(row["cost_source"], "history") << row.dump();
  EXPECT_GT(row["cost_ratio"][0].get<double>(), 0.0) << row.dump();
  EXPECT_EQ(plan["model"]["similar_series"], 1);
  // Independent least squares of log RDE on log Δ* over the stored rows.
  std::stringstream rows(sqlite_query(dir / "g.sqlite", "SELECT delta_star, rde FROM uncertainties"));
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0, h = 0, e = 0;
  char bar = 0;
  while (rows >> h >> bar >> e) {
    sx += std::log(h), sy += std::log(e), sxx += std::log(h) * std::log(h), sxy += std::log(h) * std::log(e), n += 1;
  }
  ASSERT_EQ(n, 9);
  const double p = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(plan["model"]["p"].get<double>(), p, 1e-6 * std::abs(p));
  // Needed: down to the first grid predicted at or below the target (at least five).
  const auto& grids = plan["cases"][0]["grids"];
  std::size_t needed = 0, first_met = grids.size();
  for (std::size_t k = 0; k < grids.size(); ++k) {
    needed += grids[k]["needed"].get<bool>();
    if (first_met == grids.size() && grids[k]["predicted_rde"].get<double>() <= 0.001) first_met = k;
  }
  ASSERT_LT(first_met, grids.size());
  EXPECT_EQ(needed, std::max<std::size_t>(first_met + 1, 5));
}

}  // namespace
