// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates of external jobs (study/external_plan.h): declared per-cell
// figures, else a fit to the case's measured history, else unknown — never
// gridfree's own solver model.
#include <gtest/gtest.h>

#include <cmath>

#include "study/external_plan.h"

namespace gridfree {
namespace {

using nlohmann::json;

json external_plan_job(double n) {
  json job = json::parse(R"({"schema": "gridfree/job/1",
    "case": {"name": "c", "external": {"template_sha256": "ab", "command": ["run"], "version": "1",
                                       "template_dir": "/x"}},
    "numerics": {"grid": {"level": 0}}})");
  job["case"]["external"]["variables"] = {{"N", n}};
  job["numerics"]["grid"]["h"] = 1 / n;
  job["numerics"]["grid"]["cells"] = n * n;
  return job;
}

TEST(ExternalPlan, PowerLawFitOfMeasuredCpuSeconds) {
  // cpu = 2e-3 · cells^1.5 measured at three sizes: the fit returns the law exactly.
  std::vector<CostSample> samples;
  for (double c : {100.0, 400.0, 1600.0}) samples.push_back({c, 2e-3 * std::pow(c, 1.5)});
  double b = 0;
  EXPECT_NEAR(fit_cpu_seconds(samples, 6400, &b), 2e-3 * std::pow(6400.0, 1.5), 1e-9 * 1024);
  EXPECT_NEAR(b, 1.5, 1e-12);
  // One measured size: proportional to cells.
  EXPECT_NEAR(fit_cpu_seconds({{100, 3}}, 400, &b), 12, 1e-12);
  EXPECT_EQ(b, 1);
  EXPECT_TRUE(std::isnan(fit_cpu_seconds({}, 400)));
}

TEST(ExternalPlan, DeclaredThenHistoryThenUnknown) {
  ExternalCase c;
  const json job = external_plan_job(40);
  // Nothing declared, no history: unknown, and said so.
  ExternalJobCost none = external_job_cost(c, job, 1600, {});
  EXPECT_TRUE(std::isnan(none.cpu_s));
  EXPECT_TRUE(std::isnan(none.memory_bytes));
  EXPECT_NE(none.basis.find("unknown"), std::string::npos);
  // History of the same case on other grids (variables differ, same key).
  CostHistory history;
  history[cost_similarity_key(external_plan_job(20))].push_back({400, 2});
  EXPECT_EQ(cost_similarity_key(external_plan_job(20)), cost_similarity_key(job));
  const ExternalJobCost measured = external_job_cost(c, job, 1600, history);
  EXPECT_NEAR(measured.cpu_s, 8, 1e-12);
  EXPECT_EQ(measured.basis.rfind("history", 0), 0u);
  // Declared figures win.
  c.cpu_s_per_cell = 0.01;
  c.mb_per_cell = 0.5;
  const ExternalJobCost declared = external_job_cost(c, job, 1600, history);
  EXPECT_NEAR(declared.cpu_s, 16, 1e-12);
  EXPECT_NEAR(declared.memory_bytes, 800.0 * 1024 * 1024, 1e-3);
  // The gridfree model's text never appears for an unknown figure.
  EXPECT_EQ(human_seconds(NAN), "unknown");
  EXPECT_EQ(human_bytes(NAN), "unknown");
}

TEST(ExternalPlan, MemoryFromDeclaredThenMeasuredPeakThenUnknown) {
  // Peak = 40 MiB + 0.01 MiB per cell at three sizes: the fit is the law,
  // times the safety factor.
  std::vector<CostSample> samples;
  for (double c : {400.0, 1600.0, 6400.0}) samples.push_back({c, 1, 40 + 0.01 * c});
  EXPECT_NEAR(fit_memory_mb(samples, 25600), 40 + 256, 1e-9);
  // One measured size: its peak, scaled up with cells above it, never down.
  EXPECT_NEAR(fit_memory_mb({{400, 1, 50}}, 1600), 200, 1e-12);
  EXPECT_NEAR(fit_memory_mb({{400, 1, 50}}, 100), 50, 1e-12);
  // Noise making memory fall with cells: the largest peak, not a fit below it.
  EXPECT_NEAR(fit_memory_mb({{400, 1, 60}, {1600, 1, 55}}, 3200), 60, 1e-12);
  // Samples without a recorded peak do not count.
  EXPECT_TRUE(std::isnan(fit_memory_mb({{400, 1, 0}}, 1600)));

  ExternalCase c;
  const json job = external_plan_job(40);
  CostHistory history;
  history[cost_similarity_key(job)] = samples;
  const ExternalJobCost measured = external_job_cost(c, job, 25600, history);
  EXPECT_NEAR(measured.memory_bytes, kExternalMemorySafety * 296 * 1024 * 1024, 1e-3);
  EXPECT_EQ(measured.memory_basis.rfind("history", 0), 0u) << measured.memory_basis;
  // Declared wins; nothing: unknown, said so (never gridfree's own model).
  c.mb_per_cell = 0.5;
  EXPECT_NEAR(external_job_cost(c, job, 1600, history).memory_bytes, 800.0 * 1024 * 1024, 1e-3);
  EXPECT_EQ(external_job_cost(c, job, 1600, history).memory_basis.rfind("declared", 0), 0u);
  c.mb_per_cell.reset();
  const ExternalJobCost none = external_job_cost(c, job, 1600, {});
  EXPECT_TRUE(std::isnan(none.memory_bytes));
  EXPECT_NE(none.memory_basis.find("unknown"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
