// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker solve, run as a process (docs/INTERFACE.md §2): exit codes,
// the result document, --vtk, and the failure of centroid deposition on
// cells smaller than a particle.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "contract_job.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

// The docs/INTERFACE.md job on `cells` with `deposition` and a 2000-iteration cap.
nlohmann::json baseline_job(const std::string& deposition, const std::array<int, 3>& cells) {
  nlohmann::json job = gridfree::test::contract_job();
  job["numerics"]["grid"] = {{"cells", cells}};
  job["numerics"]["deposition"] = {{"kind", deposition}, {"fwhm_dp", 6}};
  job["numerics"]["max_iterations"] = 2000;
  return job;
}

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};

// gridfree-worker solve `args`, run in `dir` (stderr kept there).
Outcome worker_solve(const std::string& args, const fs::path& dir) {
  const auto r = gridfree::test_support::run_executable("gridfree-worker", "solve " + args, dir);
  return {r.exit_code, r.out + r.err};
}

fs::path scratch(const std::string& name) { return gridfree::test_support::fresh_scratch_dir("solve_cli", name); }

using gridfree::test_support::load_json;
using gridfree::test_support::save_json;

TEST(SolveCli, BaselineAtDeltaStar2ConvergesAndWritesEveryField) {
  const fs::path dir = scratch("baseline");
  save_json(dir / "job.json", baseline_job("diffusion", {15, 100, 5}));
  const Outcome r = worker_solve((dir / "job.json").string() + " -o " + (dir / "result.json").string() + " --vtk " +
                    (dir / "vtk").string() + " --threads 2 -q",
                              dir);
  const std::string cmd_note = "output:\n" + r.output;
  ASSERT_EQ(r.exit_code, 0) << cmd_note;
  const nlohmann::json res = load_json(dir / "result.json");
  EXPECT_EQ(res["schema"], "gridfree/result/1");
  EXPECT_EQ(res["status"], "converged");
  ASSERT_TRUE(res["srq"]["dp_star"].is_number());
  // Physically sensible: the series-resistance estimate of the bed is ≈ 1174
  // (tests/verification/flow/bursting_bubble_test.cpp); the bubble bypass
  // lowers it. A broad band catches gross errors (units, signs, drag law).
  EXPECT_GT(res["srq"]["dp_star"].get<double>(), 800.0);
  EXPECT_LT(res["srq"]["dp_star"].get<double>(), 1400.0);
  EXPECT_EQ(res["grid"]["cells"], nlohmann::json({15, 100, 5}));
  EXPECT_NEAR(res["grid"]["delta_star"].get<double>(), 2.0, 1e-12);
  for (const char* key : {"job_hash", "iterations", "version"}) EXPECT_TRUE(res.contains(key)) << key;
  EXPECT_EQ(res["job_hash"].get<std::string>().size(), 64u);
  EXPECT_LT(res["residuals"]["continuity"].get<double>(), 1e-5);
  EXPECT_LT(res["residuals"]["momentum"].get<double>(), 1e-5);
  EXPECT_GT(res["timing"]["wall_s"].get<double>(), 0.0);
  EXPECT_GE(res["timing"]["cpu_s"].get<double>(), 0.0);
  EXPECT_GT(res["memory"]["peak_rss_mb"].get<double>(), 0.0);
  EXPECT_EQ(res["diagnostics"]["particles"], 4649);
  EXPECT_GT(res["diagnostics"]["max_solids_fraction"].get<double>(), 0.2);
  EXPECT_LT(res["diagnostics"]["mass_imbalance"].get<double>(), 1e-6);
  EXPECT_TRUE(fs::exists(dir / "vtk" / "PC1.vtk"));
  std::ifstream vtk(dir / "vtk" / "PC1.vtk");
  std::string first;
  std::getline(vtk, first);
  EXPECT_EQ(first.rfind("# vtk DataFile", 0), 0u);
}

TEST(SolveCli, ResultGoesToStdoutWithoutOutputFile) {
  const fs::path dir = scratch("stdout");
  nlohmann::json job = baseline_job("diffusion", {3, 20, 1});
  job["case"]["particles"] = {{"uniform", {{"solids_fraction", 0.3}}}};
  save_json(dir / "job.json", job);
  const Outcome r = worker_solve((dir / "job.json").string() + " -q", dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json res = nlohmann::json::parse(r.output);
  EXPECT_EQ(res["status"], "converged");
}

TEST(SolveCli, IterationCapExitsThreeWithNotConvergedAndTheReason) {
  const fs::path dir = scratch("capped");
  nlohmann::json job = baseline_job("diffusion", {15, 100, 5});
  job["numerics"]["max_iterations"] = 2;
  save_json(dir / "job.json", job);
  const Outcome r = worker_solve((dir / "job.json").string() + " -o " + (dir / "result.json").string() + " -q", dir);
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const nlohmann::json res = load_json(dir / "result.json");
  EXPECT_EQ(res["status"], "not_converged");
  EXPECT_EQ(res["iterations"], 2);
  EXPECT_NE(res["reason"].get<std::string>().find("not converged after 2 iterations"), std::string::npos)
      << res["reason"];
}

TEST(SolveCli, CentroidDepositionFailsBelowDeltaStarOne) {
  const fs::path dir = scratch("centroid");
  save_json(dir / "job.json", baseline_job("centroid", {60, 400, 20}));  // Δ* = 0.5
  const Outcome r = worker_solve((dir / "job.json").string() + " -o " + (dir / "result.json").string() + " -q", dir);
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const nlohmann::json res = load_json(dir / "result.json");
  EXPECT_EQ(res["status"], "invalid");  // no gas in a cell: no solution exists, nothing was iterated
  EXPECT_EQ(res["outcome"], "invalid");
  EXPECT_EQ(res["iterations"], 0);
  const std::string reason = res["reason"];
  EXPECT_NE(reason.find("solids fraction"), std::string::npos) << reason;
  EXPECT_NE(reason.find("diffusion deposition"), std::string::npos) << reason;
  EXPECT_TRUE(!res.contains("srq") || !res["srq"].contains("dp_star") || res["srq"]["dp_star"].is_null());
}

TEST(SolveCli, JobWithoutGridIsInvalidInputAndWritesNothing) {
  const fs::path dir = scratch("nogrid");
  nlohmann::json job = baseline_job("diffusion", {15, 100, 5});
  job["numerics"].erase("grid");
  save_json(dir / "job.json", job);
  const Outcome r = worker_solve((dir / "job.json").string() + " -o " + (dir / "result.json").string(), dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("grid"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "result.json"));
}

TEST(SolveCli, MissingJobFileIsInvalidInput) {
  const Outcome r = worker_solve("/nonexistent/job.json -q", scratch("missing"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
}

// The worker binary with an environment prefix, through the shell.
gridfree::test_support::CommandRun run_with_env(const std::string& env, const std::string& args, const fs::path& dir) {
  const std::string worker = std::string(GRIDFREE_BIN_DIR) + "/gridfree-worker";
  return gridfree::test_support::run_command("env " + env + " '" + worker + "' " + args, dir / "stderr.txt");
}

TEST(SolveCli, WithoutThreadsOptionOmpNumThreadsDecides) {
  const fs::path dir = scratch("omp_num_threads");
  nlohmann::json job = baseline_job("diffusion", {3, 20, 1});
  job["case"]["particles"] = {{"uniform", {{"solids_fraction", 0.3}}}};
  save_json(dir / "job.json", job);
  const auto one = run_with_env("OMP_NUM_THREADS=1", "solve " + (dir / "job.json").string(), dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.err.find("with 1 thread(s)"), std::string::npos) << one.err;
  const auto forced = run_with_env("OMP_NUM_THREADS=1", "solve " + (dir / "job.json").string() + " --threads 2", dir);
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(forced.err.find("with 2 thread(s)"), std::string::npos) << forced.err;
}

// libgomp prints its settings at load (OMP_DISPLAY_ENV=verbose): the worker
// loads it twice when it sets the passive default (GOMP_SPINCOUNT 0 the
// second time), once when the user set a policy.
TEST(SolveCli, IdleThreadsSleepUnlessTheUserChoseAPolicy) {
  const fs::path dir = scratch("wait_policy");
  const auto def = run_with_env("-u OMP_WAIT_POLICY -u GOMP_SPINCOUNT OMP_DISPLAY_ENV=verbose", "--version", dir);
  ASSERT_EQ(def.exit_code, 0) << def.err;
  const std::string key = "GOMP_SPINCOUNT = '";
  const auto last = def.err.rfind(key);
  ASSERT_NE(last, std::string::npos) << def.err;
  EXPECT_EQ(def.err.substr(last + key.size(), 2), "0'") << def.err;
  const auto user = run_with_env("-u OMP_WAIT_POLICY GOMP_SPINCOUNT=1234 OMP_DISPLAY_ENV=verbose", "--version", dir);
  ASSERT_EQ(user.exit_code, 0) << user.err;
  EXPECT_NE(user.err.find(key + "1234'"), std::string::npos) << user.err;
  EXPECT_EQ(user.err.find(key + "0'"), std::string::npos) << user.err;
}

TEST(SolveCli, UnknownStartIsInvalidInput) {
  const fs::path dir = scratch("bad_start");
  save_json(dir / "job.json", baseline_job("diffusion", {3, 20, 1}));
  const Outcome r = worker_solve((dir / "job.json").string() + " --start sideways -q", dir);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--start"), std::string::npos) << r.output;
}

// -o into a missing folder or onto a folder: exit 2 naming the path and the
// reason, refused before solving (no "solving" line, nothing written).
TEST(SolveCli, UnwritableOutputIsInvalidInputBeforeSolving) {
  const fs::path dir = scratch("bad_output");
  save_json(dir / "job.json", baseline_job("diffusion", {15, 100, 5}));
  const std::string missing = (dir / "no_such_folder" / "result.json").string();
  const Outcome a = worker_solve((dir / "job.json").string() + " -o " + missing, dir);
  EXPECT_EQ(a.exit_code, 2) << a.output;
  EXPECT_NE(a.output.find(missing), std::string::npos) << a.output;
  EXPECT_NE(a.output.find("does not exist"), std::string::npos) << a.output;
  EXPECT_EQ(a.output.find("solving"), std::string::npos) << a.output;
  const Outcome b = worker_solve((dir / "job.json").string() + " -o " + dir.string(), dir);
  EXPECT_EQ(b.exit_code, 2) << b.output;
  EXPECT_NE(b.output.find("is an existing folder"), std::string::npos) << b.output;
  EXPECT_EQ(b.output.find("solving"), std::string::npos) << b.output;
}

}  // namespace
