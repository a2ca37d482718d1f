// `gridfree run` on an external study (docs/EXTERNAL.md "The study"): the
// poly test solver (tests/fixtures/external/poly) gives f(h) = 1 + 0.5 h²,
// so the series must come out converged with f0 = 1 and p = 2; a second run
// reruns nothing, a collect edit re-collects without rerunning, a template
// edit reruns every job. Solver runs are counted with the file the solver
// appends to (SOLVER_RUNS). The jobs run through gridfree-worker's own
// external driver.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

const fs::path kRealWorker = fs::path(GRIDFREE_BIN_DIR) / "gridfree-worker";

nlohmann::json poly_study_doc(const fs::path& dir) {
  auto doc = nlohmann::json::parse(R"({"schema": "gridfree/study/1", "name": "poly",
    "cases": {"poly": {"external": {
      "template": "poly", "render": ["input.txt"],
      "variables": {"h_cell": "1 / N"}, "h": "1 / N", "cells": "N ^ 2",
      "command": ["sh", "solve.sh"], "version": "poly 1",
      "collect": {"quantities": {
        "f": {"units": "J", "description": "the test function", "file": "out.dat", "column": 1}}}}}},
    "grids": {"variables": {"N": [4, 6, 8, 12, 16]}}})");
  doc["cases"]["poly"]["external"]["setup"] = {"export SOLVER_RUNS=" + shell_quote((dir / "runs.txt").string())};
  return doc;
}

int lines_of(const fs::path& f) {
  std::ifstream in(f);
  int n = 0;
  std::string line;
  while (std::getline(in, line)) ++n;
  return n;
}

CommandRun run_in(const fs::path& dir, const std::string& args, const fs::path& worker) {
  return gridfree_in(dir, args, "GRIDFREE_WORKER=" + shell_quote(worker.string()) +
                                    " GRIDFREE_FAKE_LOG=" + shell_quote((dir / "driver.log").string()));
}

double query_number(const std::string& s) { return s.empty() ? -1e300 : std::stod(s); }

TEST(ExternalStudyCli, ConvergesToTheAnalyticLimitAndRerunsOnlyWhatChanged) {
  const fs::path& worker = kRealWorker;
  const auto dir = gridfree::test_support::fresh_scratch_dir("external_study_cli_test", "real");
  fs::copy(gridfree::test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
           fs::copy_options::recursive);
  auto doc = poly_study_doc(dir);
  std::ofstream(dir / "study.json") << doc.dump(2);
  const auto db = dir / "g.sqlite";

  const CommandRun first = run_in(dir, "run study.json -j 2 --db g.sqlite", worker);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 5);
  const std::string f_series = "(SELECT id FROM series WHERE quantity = 'f')";
  EXPECT_EQ(sqlite_query(db, "SELECT verdict FROM series WHERE quantity = 'f'"), "converged");
  // f = 1 + 0.5 h^2 exactly (17 digits written): f0 and p to round-off.
  const double f0 = query_number(sqlite_query(db, "SELECT f0 FROM extrapolations WHERE chosen = 1 AND series_id = " + f_series));
  const double p = query_number(sqlite_query(db, "SELECT p FROM extrapolations WHERE chosen = 1 AND series_id = " + f_series));
  EXPECT_NEAR(f0, 1.0, 1e-9);
  EXPECT_NEAR(p, 2.0, 1e-6);

  // The same study again: nothing reruns.
  const CommandRun second = run_in(dir, "run study.json -j 2 --db g.sqlite", worker);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 5);

  // Another quantity read from the same output: re-collected, not rerun.
  doc["cases"]["poly"]["external"]["collect"]["quantities"]["h_read"] = {
      {"units", "m"}, {"file", "out.dat"}, {"column", 0}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  const CommandRun recollect = run_in(dir, "run study.json -j 2 --db g.sqlite --replace", worker);
  ASSERT_EQ(recollect.exit_code, 0) << recollect.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 5);
  EXPECT_NE(recollect.err.find("re-collected 5 finished job(s)"), std::string::npos) << recollect.err;
  // h read back is h itself: f0 = 0, p = 1.
  const std::string h_series = "(SELECT id FROM series WHERE quantity = 'h_read')";
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM v_results WHERE series_id = " + h_series), "5");
  const double h0 = query_number(sqlite_query(db, "SELECT f0 FROM extrapolations WHERE chosen = 1 AND series_id = " + h_series));
  EXPECT_NEAR(h0, 0.0, 1e-9);

  // The template's solver edited (f = 2 + 0.5 h^2): every job reruns, without --replace.
  {
    std::ifstream in(dir / "poly/solve.sh");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("1 + 0.5 * h");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 1, "2");
    std::ofstream(dir / "poly/solve.sh") << text;
  }
  const CommandRun edited = run_in(dir, "run study.json -j 2 --db g.sqlite", worker);
  ASSERT_EQ(edited.exit_code, 0) << edited.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 10);
  const double f0_edited =
      query_number(sqlite_query(db, "SELECT f0 FROM extrapolations WHERE chosen = 1 AND series_id = " + f_series));
  EXPECT_NEAR(f0_edited, 2.0, 1e-9);
}

}  // namespace
