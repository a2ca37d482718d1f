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
  const CostFit fit = fit_cpu_seconds(samples, 6400);
  EXPECT_NEAR(fit.value, 2e-3 * std::pow(6400.0, 1.5), 1e-9 * 1024);
  EXPECT_NEAR(fit.exponent, 1.5, 1e-12);
  EXPECT_EQ(fit.sizes, 3u);
  // One measured size: its time for a grid no larger (CPU does not fall
  // with cells), unknown above it (a start-up time is not scaled by cells).
  EXPECT_NEAR(fit_cpu_seconds({{100, 3}}, 100).value, 3, 1e-12);
  EXPECT_NEAR(fit_cpu_seconds({{100, 3}}, 50).value, 3, 1e-12);
  const CostFit above = fit_cpu_seconds({{100, 3}, {100, 2.5}}, 400);
  EXPECT_TRUE(std::isnan(above.value));
  EXPECT_EQ(above.sizes, 1u);
  EXPECT_EQ(above.basis.rfind("unknown above 100 cells", 0), 0u) << above.basis;
  EXPECT_TRUE(std::isnan(fit_cpu_seconds({}, 400).value));
}

// The issue's case: OpenFOAM's laplacianFoam at 8 x 8 cells peaked at
// 107 MiB, nearly all of it the code's fixed footprint. Scaled with cells
// to 256 x 256 that claimed 160.7 GiB (real peak of that grid: 200 MiB).
// One size must give nothing above it, never the scaled figure.
TEST(ExternalPlan, OneMeasuredSizeNeverScalesAFixedFootprintWithCells) {
  const std::vector<CostSample> one = {{64, 0.5, 107}};
  const CostFit fine = fit_memory_mb(one, 65536);
  EXPECT_TRUE(std::isnan(fine.value)) << fine.value;
  EXPECT_NE(fine.basis.find("one measured size (107 MiB at 64 cells)"), std::string::npos) << fine.basis;
  ExternalCase c;
  const ExternalJobCost cost = external_job_cost(c, external_plan_job(256), 65536,
                                                 CostHistory{{cost_similarity_key(external_plan_job(8)), one}});
  EXPECT_TRUE(std::isnan(cost.memory_bytes)) << cost.memory_bytes / (1024.0 * 1024 * 1024) << " GiB";
  EXPECT_TRUE(std::isnan(cost.cpu_s));
  EXPECT_EQ(cost.memory_basis.rfind("unknown above 64 cells", 0), 0u) << cost.memory_basis;
  // The measured grid itself (and any smaller one): its peak x the safety factor.
  const ExternalJobCost same = external_job_cost(c, external_plan_job(8), 64,
                                                 CostHistory{{cost_similarity_key(external_plan_job(8)), one}});
  EXPECT_NEAR(same.memory_bytes, kExternalMemorySafety * 107 * 1024 * 1024, 1e-3);
  EXPECT_NEAR(same.cpu_s, 0.5, 1e-12);
}

// Two sizes of a known model, peak = 100 MiB + 0.0015 MiB per cell (a
// fixed footprint and a per-cell part), measured at 64 and 1024 cells:
// the fit separates them exactly, and 65 536 cells get 100 + 98.304 MiB
// x 1.5, not 100 MiB scaled by cells.
TEST(ExternalPlan, TwoSizesSeparateTheFixedFootprintFromThePerCellPart) {
  const auto peak = [](double cells) { return 100 + 0.0015 * cells; };
  const std::vector<CostSample> two = {{64, 0.4, peak(64)}, {1024, 1.6, peak(1024)}};
  const CostFit fit = fit_memory_mb(two, 65536);
  EXPECT_NEAR(fit.fixed, 100, 1e-9);
  EXPECT_NEAR(fit.per_cell, 0.0015, 1e-12);
  EXPECT_NEAR(fit.value, peak(65536), 1e-9);
  EXPECT_EQ(fit.sizes, 2u);
  ExternalCase c;
  const ExternalJobCost cost = external_job_cost(c, external_plan_job(256), 65536,
                                                 CostHistory{{cost_similarity_key(external_plan_job(8)), two}});
  EXPECT_NEAR(cost.memory_bytes, kExternalMemorySafety * peak(65536) * 1024 * 1024, 1e-3);
  EXPECT_NE(cost.memory_basis.find("100 MiB + 0.0015 MiB per cell"), std::string::npos) << cost.memory_basis;
  // CPU from the same two sizes: 0.4 s at 64, 1.6 s at 1024 cells is
  // cells^0.5 exactly (0.4 · (65536/64)^0.5 = 12.8 s).
  EXPECT_NEAR(cost.cpu_s, 12.8, 1e-9);
  EXPECT_NE(cost.basis.find("at 2 sizes, CPU s ∝ cells^0.50"), std::string::npos) << cost.basis;
}

// A declared per-cell figure with one measured size: only what grows with
// cells is scaled; the footprint the measurement shows beyond the figure
// is added once.
TEST(ExternalPlan, DeclaredPerCellFigurePlusTheMeasuredFixedPart) {
  ExternalCase c;
  c.mb_per_cell = 0.001;
  c.cpu_s_per_cell = 1e-4;
  const std::vector<CostSample> one = {{64, 0.5064, 107}};
  const ExternalJobCost cost = external_job_cost(c, external_plan_job(256), 65536,
                                                 CostHistory{{cost_similarity_key(external_plan_job(8)), one}});
  const double fixed_mb = 107 - 0.001 * 64;
  EXPECT_NEAR(cost.memory_bytes, (kExternalMemorySafety * fixed_mb + 0.001 * 65536) * 1024 * 1024, 1e-3);
  EXPECT_NEAR(cost.cpu_s, 0.5 + 1e-4 * 65536, 1e-9);
  EXPECT_EQ(cost.memory_basis.rfind("declared 0.001 MB per cell + the fixed footprint", 0), 0u) << cost.memory_basis;
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
  history[cost_similarity_key(external_plan_job(20))].push_back({800, 4});
  EXPECT_EQ(cost_similarity_key(external_plan_job(20)), cost_similarity_key(job));
  const ExternalJobCost measured = external_job_cost(c, job, 1600, history);
  EXPECT_NEAR(measured.cpu_s, 8, 1e-12);
  EXPECT_EQ(measured.basis.rfind("history", 0), 0u);
  // Declared figures win (the history shows no time beyond 0.01 s per cell
  // and no peak memory).
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
  EXPECT_NEAR(fit_memory_mb(samples, 25600).value, 40 + 256, 1e-9);
  // One measured size: its peak for a grid no larger; unknown above it.
  EXPECT_TRUE(std::isnan(fit_memory_mb({{400, 1, 50}}, 1600).value));
  EXPECT_NEAR(fit_memory_mb({{400, 1, 50}}, 100).value, 50, 1e-12);
  // Noise making memory fall with cells: the largest peak, not a fit below it.
  EXPECT_NEAR(fit_memory_mb({{400, 1, 60}, {1600, 1, 55}}, 3200).value, 60, 1e-12);
  // Samples without a recorded peak do not count.
  EXPECT_TRUE(std::isnan(fit_memory_mb({{400, 1, 0}}, 1600).value));

  ExternalCase c;
  const json job = external_plan_job(40);
  CostHistory history;
  history[cost_similarity_key(job)] = samples;
  const ExternalJobCost measured = external_job_cost(c, job, 25600, history);
  EXPECT_NEAR(measured.memory_bytes, kExternalMemorySafety * 296 * 1024 * 1024, 1e-3);
  EXPECT_EQ(measured.memory_basis.rfind("history", 0), 0u) << measured.memory_basis;
  // Declared wins (the measured peaks lie below 0.5 MiB per cell: no fixed
  // part beyond it); nothing: unknown, said so (never gridfree's own model).
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
