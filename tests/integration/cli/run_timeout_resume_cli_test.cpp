// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run --timeout` with the real worker (docs/ORCHESTRATOR.md,
// "Checkpoints"): a job stopped by the run's timeout at about half its
// outer iterations writes its checkpoint, is queued again without spending
// an attempt, and the next attempt of the same `run` resumes from it. The
// stored result has the dp* and iteration count of an uninterrupted `run`
// of the same study (computed here first), the resumed attempt computes
// only the iterations after the checkpoint, and the checkpoint is deleted
// once the result is stored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::CommandRun;
using gridfree::test_support::quickstart_document;
using gridfree::test_support::sqlite_query;

// The quickstart case PC1 on one grid, Δ* = 1.5 (20×133×7 = 18 620 cells,
// started from its nested-start level of 10×67×4 cells), with the steady
// tolerance tightened from 1e-5 to 1e-7 so that the solve takes enough
// outer iterations on its own grid (165, ≈ 3 s on one thread, against a
// setup of ≈ 0.4 s) for a timeout to land in the middle of them. A stop
// during the coarse level leaves no checkpoint (docs/SOLVER.md), so the
// timeout is placed after it. Every later attempt pays the setup again and
// must finish at least one iteration inside the timeout to leave a fresh
// checkpoint (else the stop spends an attempt, by design); half the
// iterations' time is the margin for that, about 1.5 s. With 1e-6 (73
// iterations, 0.7 s of margin) a loaded machine once let an attempt's
// setup eat the margin. The test runs alone (RUN_SERIAL, tests/CMakeLists.txt):
// under the sanitizers beside other tests, an attempt once finished no outer
// iteration inside the timeout placed from its reference and spent itself.
void write_study(const fs::path& dir) {
  auto doc = quickstart_document();
  doc["name"] = "resume";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"PC1", pc1}};
  doc.erase("factors");  // the defaults: one series
  doc.erase("design");
  doc["grids"] = {{"delta_star", {1.5}}};
  doc["numerics"]["tolerances"]["steady"] = 1e-7;
  std::ofstream(dir / "resume.json") << doc.dump(2);
}

// `gridfree run` with the real worker, one thread per job (-j = cores; the
// study has one job), so both runs below compute with the same thread count.
CommandRun run(const fs::path& dir, const std::string& timeout) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return gridfree::test_support::run_command("cd '" + dir.string() + "' && env -u GRIDFREE_WORKER '" +
                                                 std::string(GRIDFREE_BIN_DIR) + "/gridfree' run resume.json -j " +
                                                 std::to_string(cores) + " --timeout " + timeout + " --db g.sqlite",
                                             dir / "stderr.txt");
}

nlohmann::json stored_result(const fs::path& db) {
  const std::string text = sqlite_query(db, "SELECT result_json FROM results");
  return text.empty() ? nlohmann::json() : nlohmann::json::parse(text);
}

int files_named(const fs::path& root, const std::string& name) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(root)) n += e.path().filename() == name;
  return n;
}

TEST(RunTimeoutResume, ATimedOutJobResumesFromItsCheckpointWithoutSpendingAnAttempt) {
  // Reference: the same study, uninterrupted (no timeout).
  const fs::path ref_dir = gridfree::test_support::fresh_scratch_dir("run_timeout_resume_cli", "reference");
  write_study(ref_dir);
  const CommandRun ref_run = run(ref_dir, "none");
  ASSERT_EQ(ref_run.exit_code, 0) << ref_run.err;
  const nlohmann::json ref = stored_result(ref_dir / "g.sqlite");
  ASSERT_TRUE(ref.is_object()) << ref_run.err;
  const int n_ref = ref["iterations"].get<int>();
  const double dp_ref = ref["srq"]["dp_star"].get<double>();
  const double wall_ref = ref["timing"]["wall_s"].get<double>();
  const double iterations_ref = ref["extra"]["timing"]["iterations_s"].get<double>();
  ASSERT_GE(n_ref, 20) << "too few outer iterations to stop in the middle";
  EXPECT_FALSE(ref["extra"].contains("resumed_from_iteration"));

  // Timed out halfway through the reference's iterations on the job's own
  // grid (after the setup and the nested start; at least 1 s).
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("run_timeout_resume_cli", "timed_out");
  write_study(dir);
  const double timeout_s = std::max(1.0, wall_ref - 0.5 * iterations_ref);
  char timeout[32];
  std::snprintf(timeout, sizeof timeout, "%.2f", timeout_s);
  const CommandRun r = run(dir, timeout);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path db = dir / "g.sqlite";

  // Stopped by the timeout at least once, each time with a checkpoint: the
  // job was released (attempt not spent), never retried or failed.
  const int stops = std::stoi(sqlite_query(db, "SELECT COUNT(*) FROM events WHERE kind = 'release' AND message LIKE "
                                      "'timed out%checkpoint kept%'"));
  EXPECT_GE(stops, 1) << sqlite_query(db, "SELECT kind, message FROM events");
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM events WHERE kind IN ('retry', 'requeue')"), "0");
  EXPECT_EQ(sqlite_query(db, "SELECT status || ' ' || attempts FROM jobs"), "done 1")
      << "timeout " << timeout << " s; events:\n"
      << sqlite_query(db, "SELECT kind, message FROM events");

  // The stored result continues the last checkpoint (iteration k > 0) to
  // the reference's total: the checkpoint holds everything the next outer
  // iteration reads, so the resumed run repeats iterations k+1..n of the
  // uninterrupted one. The attempts together computed n_ref iterations;
  // restarting from zero would have computed n_ref + k.
  const nlohmann::json res = stored_result(db);
  ASSERT_TRUE(res.is_object());
  EXPECT_EQ(res["status"], "converged");
  ASSERT_TRUE(res["extra"].contains("resumed_from_iteration")) << res.dump();
  const int k = res["extra"]["resumed_from_iteration"].get<int>();
  const int n = res["iterations"].get<int>();
  EXPECT_GT(k, 0);
  EXPECT_LT(k, n);
  EXPECT_EQ(n, n_ref);
  EXPECT_LT(n - k, n_ref);
  // dp* within 1e-6 relative of the uninterrupted run (the required
  // tolerance): same job, same thread count, and the same arithmetic from
  // the same state, so bit-identical is expected and 1e-6 leaves room for
  // nothing but round-off. A restored state that differed at all would
  // change the path to convergence, which the iteration count above shows.
  const double dp = res["srq"]["dp_star"].get<double>();
  EXPECT_LE(std::fabs(dp - dp_ref), 1e-6 * std::fabs(dp_ref)) << dp << " vs " << dp_ref;

  // The checkpoint went once the result was stored.
  EXPECT_EQ(files_named(dir / "g.sqlite.runs", "result.json"), 1);
  EXPECT_EQ(files_named(dir / "g.sqlite.runs", "checkpoint.bin"), 0);

  RecordProperty("iterations_uninterrupted", n_ref);
  RecordProperty("resumed_from_iteration", k);
  RecordProperty("timeout_stops", stops);
  std::printf("uninterrupted: %d iterations, %.2f s; timeout %.2f s: %d stop(s), last checkpoint at %d, "
              "resumed for %d; dp* %.12g vs %.12g (relative difference %.3g)\n",
              n_ref, wall_ref, timeout_s, stops, k, n - k, dp, dp_ref, std::fabs(dp - dp_ref) / std::fabs(dp_ref));
}

}  // namespace
