// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run` on an external study (docs/EXTERNAL.md "The study"): the
// poly test solver (tests/fixtures/external/poly) gives f(h) = 1 + 0.5 h²,
// so the series must come out converged with f0 = 1 and p = 2; a second run
// reruns nothing, a collect edit re-collects without rerunning, a template
// edit reruns every job. Solver runs are counted with the file the solver
// appends to (SOLVER_RUNS). The jobs run through gridfree-worker's own
// external driver.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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

std::string ext_first_line(const fs::path& f) {
  std::ifstream in(f);
  std::string line;
  std::getline(in, line);
  return line;
}

std::string ext_file_text(const fs::path& f) {
  std::ifstream in(f);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_poly_dir(const std::string& name) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("external_study_cli_test", name);
  fs::copy(gridfree::test_support::kSourceDir / "tests/fixtures/external/poly", dir / "poly",
           fs::copy_options::recursive);
  std::ofstream(dir / "study.json") << poly_study_doc(dir).dump(2);
  return dir;
}

// The jobs' run folders under g.sqlite.runs: <2 hex>/<hash>, each shard non-empty.
int run_folder_count(const fs::path& runs, bool* empty_shard) {
  int n = 0;
  for (const auto& shard : fs::directory_iterator(runs)) {
    if (!shard.is_directory() || shard.path().filename().string().size() != 2) continue;
    if (fs::is_empty(shard.path())) *empty_shard = true;
    for (const auto& d : fs::directory_iterator(shard.path())) n += d.is_directory() ? 1 : 0;
  }
  return n;
}

// Nothing is deleted without being asked (docs/ORCHESTRATOR.md "Unneeded
// jobs and gc"): a template edit keeps the old jobs with their results and
// run folders, its revert reuses them and runs nothing; `gc --dry-run`
// lists them and removes nothing; `gc` removes exactly them, their folders
// and the shard folders they leave empty.
TEST(ExternalStudyCli, ATemplateEditAndItsRevertRerunNothingAndGcRemovesOnlyTheUnneeded) {
  const auto dir = fresh_poly_dir("revert_gc");
  const auto db = dir / "g.sqlite";
  const auto runs = dir / "g.sqlite.runs";
  ASSERT_EQ(run_in(dir, "run study.json -j 2 --db g.sqlite", kRealWorker).exit_code, 0);
  const std::string original = ext_file_text(dir / "poly/solve.sh");
  std::string edited = original;
  edited.replace(edited.find("1 + 0.5 * h"), 1, "2");
  std::ofstream(dir / "poly/solve.sh") << edited;
  const CommandRun changed = run_in(dir, "run study.json -j 2 --db g.sqlite", kRealWorker);
  ASSERT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_NE(changed.err.find("5 job(s) no study needs any more kept"), std::string::npos) << changed.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 10);
  bool empty_shard = false;
  EXPECT_EQ(run_folder_count(runs, &empty_shard), 10);

  std::ofstream(dir / "poly/solve.sh") << original;  // the edit reverted
  const CommandRun reverted = run_in(dir, "run study.json -j 2 --db g.sqlite", kRealWorker);
  ASSERT_EQ(reverted.exit_code, 0) << reverted.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 10) << "the reverted template's jobs were kept: nothing reruns";
  EXPECT_NE(reverted.err.find("(0 new, 5 already done)"), std::string::npos) << reverted.err;
  EXPECT_NEAR(query_number(sqlite_query(db, "SELECT f0 FROM extrapolations e JOIN series s ON s.id = e.series_id "
                                            "WHERE e.chosen = 1 AND s.quantity = 'f'")),
              1.0, 1e-9);

  const std::string unneeded = "SELECT COUNT(*) FROM jobs WHERE id NOT IN (SELECT job_id FROM study_jobs)";
  const CommandRun dry = run_in(dir, "gc --dry-run --db g.sqlite", kRealWorker);
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_EQ(dry.out.rfind("would remove 5 job(s) no study needs any more (", 0), 0u) << dry.out;
  EXPECT_NE(dry.out.find(" poly "), std::string::npos) << dry.out;
  EXPECT_NE(dry.out.find("KiB"), std::string::npos) << dry.out;  // sizes on disk
  EXPECT_EQ(sqlite_query(db, unneeded), "5");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM jobs"), "10");
  EXPECT_EQ(run_folder_count(runs, &empty_shard), 10);

  const std::string kept_hashes = sqlite_query(db, "SELECT group_concat(job_hash) FROM (SELECT job_hash FROM jobs "
                                                   "WHERE id IN (SELECT job_id FROM study_jobs) ORDER BY job_hash)");
  const CommandRun gc = run_in(dir, "gc --db g.sqlite", kRealWorker);
  ASSERT_EQ(gc.exit_code, 0) << gc.err;
  EXPECT_EQ(gc.out.rfind("removed 5 job(s) no study needs any more (", 0), 0u) << gc.out;
  EXPECT_EQ(sqlite_query(db, unneeded), "0");
  EXPECT_EQ(sqlite_query(db, "SELECT group_concat(job_hash) FROM (SELECT job_hash FROM jobs ORDER BY job_hash)"),
            kept_hashes);
  EXPECT_EQ(run_folder_count(runs, &empty_shard), 5);
  EXPECT_FALSE(empty_shard) << "a shard folder left empty";
  std::istringstream kept(kept_hashes);  // the study's own folders are all there
  for (std::string hash; std::getline(kept, hash, ',');)
    EXPECT_TRUE(fs::exists(runs / hash.substr(0, 2) / hash / "result.json")) << hash;
  const CommandRun again = run_in(dir, "run study.json -j 2 --db g.sqlite", kRealWorker);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(lines_of(dir / "runs.txt"), 10);
}

// Memory of an external job (docs/EXTERNAL.md "Cost, timeouts, memory"):
// never gridfree's own solver model. Without a declared or measured figure
// the first job runs alone within the memory budget, the smallest grid
// first; afterwards `plan` shows the measured peak memory's estimate. The
// plan's grid table and the report name h and the value, not Δ* and DP*.
TEST(ExternalStudyCli, MemoryIsUnknownUntilMeasuredAndPlanShowsTheMeasuredEstimate) {
  const auto dir = fresh_poly_dir("memory");
  const CommandRun first = run_in(dir, "run study.json -j 2 --db g.sqlite --memory-budget 4G", kRealWorker);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  // The smallest grid (N = 4, h = 0.25) probes alone: the largest would be first by the budget's rule otherwise.
  EXPECT_EQ(ext_first_line(dir / "runs.txt"), "run h=0.25");
  EXPECT_NE(first.err.find("memory unknown (no cost.mb_per_cell and no finished job of the case yet): it runs alone"),
            std::string::npos)
      << first.err;
  // One measured size says nothing above it: the next grid (N = 6, 36 cells)
  // probes alone too; from two sizes on, each start says where its estimates come from.
  {
    std::ifstream runs(dir / "runs.txt");
    std::string line;
    std::getline(runs, line);
    std::getline(runs, line);
    EXPECT_EQ(line.rfind("run h=0.1666", 0), 0u) << line;
  }
  EXPECT_NE(first.err.find("memory unknown above 16 cells: one measured size"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find("(history: peak memory of 2 finished job(s) of the case at 2 sizes"), std::string::npos)
      << first.err;
  const double peak = query_number(sqlite_query(dir / "g.sqlite", "SELECT MAX(peak_rss_mb) FROM results"));
  ASSERT_GT(peak, 0);
  // The report speaks of h and the value, not of Δ* and DP* (docs/REPORTS.md).
  const std::string md = ext_file_text(dir / "reports/poly/report.md");
  EXPECT_EQ(md.find("Δ*"), std::string::npos) << md;
  EXPECT_EQ(md.find("DP*"), std::string::npos) << md;
  for (const char* csv : {"grids.csv", "failures.csv", "cost.csv", "stability.csv"}) {
    const std::string header = ext_first_line(dir / "reports/poly" / csv);
    EXPECT_EQ(header.find("delta_star"), std::string::npos) << csv << ": " << header;
    EXPECT_EQ(header.find("dp_star"), std::string::npos) << csv << ": " << header;
  }
  EXPECT_NE(ext_first_line(dir / "reports/poly/grids.csv").find(",h,"), std::string::npos);
  EXPECT_NE(ext_first_line(dir / "reports/poly/grids.csv").find(",value,"), std::string::npos);

  const CommandRun plan = run_in(dir, "plan study.json --db g.sqlite", kRealWorker);
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_NE(plan.out.find("max memory, poly f: "), std::string::npos) << plan.out;
  EXPECT_NE(plan.out.find("from history: peak memory of 5 finished job(s) of the case"), std::string::npos) << plan.out;
  // The grid table: h as declared and cells, no Δ* and no "nx x ny x nz".
  EXPECT_NE(plan.out.find("h of poly: h = 1 / N"), std::string::npos) << plan.out;
  EXPECT_EQ(plan.out.find("nx x ny x nz"), std::string::npos) << plan.out;
  EXPECT_EQ(plan.out.find("Δ*"), std::string::npos) << plan.out;
  const CommandRun json = run_in(dir, "plan study.json --db g.sqlite --json", kRealWorker);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  // The largest grid's estimate: at least the safety factor (1.5) x every measured peak
  // (the fit never falls below a measured peak at as many cells or fewer).
  const double mb = j["series"][0]["memory_bytes"].get<double>() / (1024.0 * 1024.0);
  EXPECT_GE(mb, 1.5 * peak * (1 - 1e-12));
  EXPECT_EQ(j["grids"][0]["h_meaning"], "h = 1 / N");
  EXPECT_EQ(j["grids"][0]["cell_count"], 16);
}

// Fake sbatch: logs its arguments to dir/sbatch_args and runs every task of
// the array at once; squeue lists nothing, so the exit_code files tell.
fs::path external_fake_slurm(const fs::path& dir) {
  const auto bin = dir / "bin";
  fs::create_directories(bin);
  auto script = [&](const std::string& name, const std::string& body) {
    std::ofstream(bin / name) << "#!/bin/sh\n" << body;
    fs::permissions(bin / name, fs::perms::owner_all);
  };
  script("sbatch", "echo \"$@\" >> " + shell_quote((dir / "sbatch_args").string()) +
                       "\nlast=0; for a; do case $a in --array=0-*) last=${a#--array=0-}; last=${last%%%*} ;; esac; "
                       "script=$a; done\n"
                       "i=0; while [ $i -le $last ]; do SLURM_ARRAY_TASK_ID=$i sh \"$script\" >/dev/null 2>&1; "
                       "i=$((i + 1)); done\necho \"7$i;cluster\"\n");
  script("squeue", "exit 0\n");
  script("scancel", "exit 0\n");
  return bin;
}

// Slurm's --mem and --time for an external code: none (and said so) before
// anything of the case was measured, then from the measured history (also
// for the later submissions of the same run); the job name names the case,
// its quantities and h, not Δ*.
TEST(ExternalStudyCli, SlurmMemoryAndTimeComeFromTheCaseAndTheJobNameSaysH) {
  const auto dir = fresh_poly_dir("slurm");
  const auto bin = external_fake_slurm(dir);
  const char* path = std::getenv("PATH");
  const std::string env = "PATH=" + shell_quote(bin.string() + ":" + (path ? path : "/usr/bin:/bin"));
  const auto slurm = [&](const std::string& args) {
    return gridfree_in(dir, args, "GRIDFREE_WORKER=" + shell_quote(kRealWorker.string()) + " " + env);
  };
  const CommandRun r1 = slurm("run study.json -j 2 --db s.sqlite --executor slurm");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  // The first submission (the smallest grids first): nothing measured yet.
  const std::string args1 = ext_first_line(dir / "sbatch_args");
  EXPECT_EQ(args1.find("--mem="), std::string::npos) << args1;
  EXPECT_EQ(args1.find("--time="), std::string::npos) << args1;
  EXPECT_NE(args1.find("--job-name=poly/poly_f_h=0.25"), std::string::npos) << args1;
  EXPECT_EQ(ext_file_text(dir / "sbatch_args").find("d*="), std::string::npos);
  EXPECT_NE(r1.err.find("memory not given, the cluster's default (external code"), std::string::npos) << r1.err;
  EXPECT_NE(r1.err.find("time limit not given, the cluster's default (external code"), std::string::npos) << r1.err;

  // One more grid: its job's limits come from the five measured ones.
  auto doc = poly_study_doc(dir);
  doc["grids"]["variables"]["N"] = {4, 6, 8, 12, 16, 24};
  std::ofstream(dir / "study.json") << doc.dump(2);
  fs::remove(dir / "sbatch_args");
  const CommandRun r2 = slurm("run study.json -j 2 --db s.sqlite --executor slurm --replace");
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const std::string args2 = ext_first_line(dir / "sbatch_args");
  EXPECT_NE(args2.find("--mem="), std::string::npos) << args2;
  EXPECT_NE(args2.find("--time="), std::string::npos) << args2;
  EXPECT_NE(args2.find("--job-name=poly/poly_f_h=0.0416667"), std::string::npos) << args2;
  EXPECT_NE(r2.err.find("from the case's measured peak memory x 1.5 x 3"), std::string::npos) << r2.err;
  EXPECT_NE(r2.err.find("from the job timeout + 1 min"), std::string::npos) << r2.err;
}

// A changed collect section submitted with `submit --replace` is re-collected
// there (no solver run); when submit cannot (no worker), a starting daemon does,
// and the series extrapolate the new values.
TEST(ExternalStudyCli, SubmitAndDaemonRecollectAChangedCollectSection) {
  const auto dir = fresh_poly_dir("recollect");
  const CommandRun first = run_in(dir, "run study.json -j 2 --db g.sqlite", kRealWorker);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ASSERT_EQ(lines_of(dir / "runs.txt"), 5);
  auto doc = poly_study_doc(dir);
  doc["cases"]["poly"]["external"]["collect"]["quantities"]["h_read"] = {{"units", "m"}, {"file", "out.dat"}, {"column", 0}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  const CommandRun submit = run_in(dir, "submit study.json --db g.sqlite --replace", kRealWorker);
  ASSERT_EQ(submit.exit_code, 0) << submit.err;
  EXPECT_NE(submit.err.find("re-collected 5 finished job(s)"), std::string::npos) << submit.err;
  const std::string h_series = "(SELECT id FROM series WHERE quantity = 'h_read')";
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM v_results WHERE series_id = " + h_series), "5");

  // Another quantity, submitted without a worker: not re-collected, said so; the daemon does it.
  doc["cases"]["poly"]["external"]["collect"]["quantities"]["f_again"] = {{"units", "J"}, {"file", "out.dat"}, {"column", 1}};
  std::ofstream(dir / "study.json") << doc.dump(2);
  const CommandRun blind = run_in(dir, "submit study.json --db g.sqlite --replace", dir / "no-such-worker");
  ASSERT_EQ(blind.exit_code, 0) << blind.err;
  EXPECT_NE(blind.err.find("could not be re-collected"), std::string::npos) << blind.err;
  const CommandRun daemon = gridfree_in(dir, "daemon --db g.sqlite -j 1",
                                        "GRIDFREE_WORKER=" + shell_quote(kRealWorker.string()) + " timeout -s INT 8");
  EXPECT_NE(daemon.err.find("re-collected 5 finished job(s)"), std::string::npos) << daemon.err;
  const std::string g_series = "(SELECT id FROM series WHERE quantity = 'f_again')";
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT COUNT(*) FROM v_results WHERE series_id = " + g_series), "5");
  EXPECT_EQ(sqlite_query(dir / "g.sqlite", "SELECT verdict FROM series WHERE quantity = 'f_again'"), "converged");
  EXPECT_EQ(lines_of(dir / "runs.txt"), 5);  // no solver run
}

}  // namespace
