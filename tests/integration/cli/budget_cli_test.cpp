// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree run --memory-budget` with the fake worker's mem mode
// (tests/fixtures/fake_worker.sh: sleeps in proportion to the worker's memory
// estimate and records its start and end): jobs that each need 60 % of the
// budget never run at once, small jobs backfill beside a big one, and the
// makespan is measured (printed; docs/ORCHESTRATOR.md "Budgets").
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/memory_estimate.h"
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

struct Interval {
  double start = 0, end = 0, bytes = 0;
};

// The study: two series (cases mem1, mem2) on Δ* = 0.3 (the big job), 2.5,
// 3.3, 5 (small jobs) of the 30 × 200 × 10 d bed.
fs::path write_budget_study(const fs::path& dir) {
  auto doc = quickstart_document();
  doc["name"] = "budget";
  const auto pc1 = doc["cases"]["PC1"];
  doc["cases"] = {{"mem1", pc1}, {"mem2", pc1}};
  doc["factors"] = {{"convection", {"superbee"}}, {"fwhm_dp", {6}}, {"drag", {"bvk"}}};
  doc["design"] = "factorial";
  doc["grids"] = {{"delta_star", {5.0, 3.3, 2.5, 0.3}}};
  const auto file = dir / "budget.json";
  std::ofstream(file) << doc.dump(2);
  return file;
}

TEST(BudgetCli, SixtyPercentJobsNeverOverlapAndSmallJobsBackfill) {
  const fs::path dir = gridfree::test_support::fresh_scratch_dir("budget_cli", "sixty");
  const auto study = write_budget_study(dir);
  // Big job: round(30/0.3) × round(200/0.3) × round(10/0.3) cells; the
  // budget makes its estimate 60 % of it.
  // The worker's model (job/memory_estimate.h): B/cell · N + base.
  const double big = gridfree::kWorkerBytesPerCell * 100 * 667 * 33 + gridfree::kWorkerBaseBytes;
  const double budget = big / 0.6;
  const fs::path times = dir / "times.txt";
  const std::string cmd = "cd " + shell_quote(dir.string()) +
                          " && GRIDFREE_WORKER=" + shell_quote(kFakeWorker.string()) +
                          " GRIDFREE_FAKE_BYTES_PER_CELL=" + std::to_string(gridfree::kWorkerBytesPerCell) +
                          " GRIDFREE_FAKE_S_PER_GIB=1.5 GRIDFREE_FAKE_TIMES=" + shell_quote(times.string()) + " " +
                          shell_quote(kGridfreeExe.string()) + " run " + shell_quote(study.string()) +
                          " -j 4 --memory-budget " + std::to_string(static_cast<long long>(budget)) + " 2>&1";
  std::string log;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof buf, p) != nullptr) log += buf;
  const int status = pclose(p);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
  EXPECT_NE(log.find("memory budget"), std::string::npos) << log;
  EXPECT_NE(log.find("thread(s) each"), std::string::npos) << log;

  std::vector<Interval> runs;
  std::ifstream in(times);
  std::string folder;
  Interval r;
  while (in >> folder >> r.start >> r.end >> r.bytes) runs.push_back(r);
  ASSERT_EQ(runs.size(), 8u) << log;
  int bigs = 0;
  bool backfilled = false;
  double first = runs[0].start, last = runs[0].end, serial = 0;
  for (const auto& a : runs) {
    first = std::min(first, a.start);
    last = std::max(last, a.end);
    serial += a.end - a.start;
    if (a.bytes > 0.5 * budget) ++bigs;
    // At the moment a job started, the estimates of every job running then
    // (its own included) fit in the budget.
    double in_use = 0;
    for (const auto& b : runs)
      if (b.start <= a.start && a.start < b.end) in_use += b.bytes;
    EXPECT_LE(in_use, budget) << "over budget when a job of " << a.bytes << " B started";
    for (const auto& b : runs)
      if (&a != &b && a.bytes > 0.5 * budget && b.bytes < 0.5 * budget && b.start < a.end && a.start < b.end)
        backfilled = true;
  }
  ASSERT_EQ(bigs, 2);
  EXPECT_TRUE(backfilled) << "no small job ran beside a big one";
  // The two big jobs must run one after the other: the makespan is at least
  // their summed durations. (That backfilling shortens the makespan is shown
  // by `backfilled` above, not by timing it: under a loaded machine the
  // makespan against the serial time is a measurement of the load.)
  double big_sum = 0;
  for (const auto& a : runs)
    if (a.bytes > 0.5 * budget) big_sum += a.end - a.start;
  const double makespan = last - first;
  EXPECT_GE(makespan, big_sum);
  std::printf("makespan %.2f s; big jobs in series %.2f s; all jobs one at a time %.2f s\n", makespan, big_sum,
              serial);
  RecordProperty("makespan_s", std::to_string(makespan));
}

}  // namespace
