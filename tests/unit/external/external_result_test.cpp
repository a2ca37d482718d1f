// SPDX-License-Identifier: GPL-3.0-or-later
// The driver's result document from a hand-made case folder (collect, so
// nothing runs): it passes schemas/result.schema.json through
// result_from_json, holds the quantities, and a nan quantity is written as
// null.
#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "external/external_driver.h"
#include "job/result.h"
#include "scratch_dir.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

ExternalJob hand_made_job() {
  ExternalJob job;
  job.version = "hand 1";
  job.grid_h = 0.05;
  QuantitySpec q;
  q.name = "ke";
  q.file = "post/*.dat";
  q.column = 1;
  job.collect.quantities.push_back(q);
  return job;
}

fs::path hand_made_case(const std::string& name, const std::string& dat) {
  const auto run = test_support::fresh_scratch_dir("external_result", name);
  fs::create_directories(run / "case" / "post");
  std::ofstream(run / "case" / "post" / "ke.dat") << dat;
  std::ofstream(run / "case" / ".gridfree_exit") << R"({"exit_code": 0, "signal": null, "wall_s": 1.5, "cpu_s": 1.25, "peak_rss_mb": 100})";
  return run;
}

TEST(ExternalResult, ValidAgainstTheResultSchema) {
  ExternalRunOptions options;
  options.run_dir = hand_made_case("valid", "# t ke\n1 0.5\n2 0.5\n");
  options.job_hash = "abc";
  options.worker_version = "gridfree test";
  const auto doc = collect_external_job(hand_made_job(), options);
  EXPECT_EQ(doc["status"], "converged");
  EXPECT_DOUBLE_EQ(doc["quantities"]["ke"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(doc["grid"]["h"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(doc["timing"]["cpu_s"].get<double>(), 1.25);
  const JobResult r = result_from_json(doc);  // throws when the schema refuses it
  EXPECT_EQ(r.status, SolveStatus::kConverged);
  EXPECT_EQ(r.job_hash, "abc");
  EXPECT_DOUBLE_EQ(r.wall_s, 1.5);
}

TEST(ExternalResult, NanQuantityWrittenAsNullAndStillValid) {
  ExternalRunOptions options;
  options.run_dir = hand_made_case("nan", "1 0.5\n2 nan\n");
  options.worker_version = "gridfree test";
  const auto doc = collect_external_job(hand_made_job(), options);
  EXPECT_EQ(doc["status"], "diverged");
  EXPECT_TRUE(doc["quantities"]["ke"].is_null());
  EXPECT_NO_THROW((void)result_from_json(doc));
}

TEST(ExternalResult, SchemaRefusesAQuantityThatIsNotANumber) {
  ExternalRunOptions options;
  options.run_dir = hand_made_case("string", "1 0.5\n");
  options.worker_version = "gridfree test";
  auto doc = collect_external_job(hand_made_job(), options);
  doc["quantities"]["ke"] = "0.5";
  EXPECT_THROW((void)result_from_json(doc), InputError);
}

}  // namespace
}  // namespace gridfree
