// SPDX-License-Identifier: GPL-3.0-or-later
// The cores rule (study/job_cores.h): cores(job) = min(cap, max(1,
// floor(value at the job's cells))), per grid; what the expression may
// read; a physical study's cores checked on its grids, its jobs'
// identities untouched.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "study/grid_listing.h"
#include "study/job_cores.h"
#include "study/study.h"
#include "study_documents.h"
#include "quickstart_study.h"

namespace gridfree {
namespace {

TEST(JobCores, EvaluatedPerGridAndCapped) {
  const std::string rule = "max(1, cells / 50000)";
  EXPECT_EQ(job_cores(rule, 4096, 8), 1);       // 0.08 → at least 1
  EXPECT_EQ(job_cores(rule, 100000, 8), 2);     // exactly 2
  EXPECT_EQ(job_cores(rule, 149999, 8), 2);     // 2.99998 → whole cores below it
  EXPECT_EQ(job_cores(rule, 150000, 8), 3);
  EXPECT_EQ(job_cores(rule, 1000000, 8), 8);    // 20 → the pool's 8
  EXPECT_EQ(job_cores(rule, 1000000, 2), 2);
  EXPECT_EQ(job_cores("0.3", 1e6, 4), 1);       // below one core: one
  EXPECT_EQ(job_cores("4", 10, 16), 4);         // a fixed number
  EXPECT_EQ(job_cores("4", 10, 0), 1);          // a cap below 1 is 1
  EXPECT_FALSE(job_cores("1 / (cells - 64)", 64, 8));  // inf: not a number of cores
  EXPECT_FALSE(job_cores("log(cells - 100)", 64, 8));  // NaN
}

TEST(JobCores, TheFieldIsAStringOrAWholeNumber) {
  EXPECT_EQ(study_cores_expression({{"cores", "cells / 1e5"}}), "cells / 1e5");
  EXPECT_EQ(study_cores_expression({{"cores", 4}}), "4");
  EXPECT_EQ(study_cores_expression({{"name", "x"}}), "");
}

TEST(JobCores, ReadsOnlyCells) {
  ProblemList ok, other, broken;
  check_cores_expression("max(1, cells / 50000)", "/cores", ok);
  EXPECT_TRUE(ok.empty());
  check_cores_expression("N ^ 2 / 1000", "/cores", other);
  ASSERT_EQ(other.problems().size(), 1u);
  EXPECT_EQ(other.problems()[0].where, "/cores");
  EXPECT_NE(other.problems()[0].reason.find("reads 'N'"), std::string::npos) << other.problems()[0].reason;
  check_cores_expression("max(1, cells /", "/cores", broken);
  ASSERT_EQ(broken.problems().size(), 1u);
  EXPECT_EQ(broken.problems()[0].where, "/cores");
}

std::vector<std::string> hashes_of(const nlohmann::json& doc) {
  std::vector<std::string> out;
  for (const auto& j : expand(test_support::study_of(doc)).jobs) out.push_back(j.hash);
  return out;
}

TEST(JobCores, PhysicalStudyKeepsItsJobHashes) {
  const auto base = test_support::quickstart_document();
  auto with = base;
  with["cores"] = "max(1, cells / 50000)";
  EXPECT_EQ(hashes_of(with), hashes_of(base));
}

TEST(JobCores, PhysicalStudyRefusesARuleThatIsNoNumberOnAGrid) {
  auto doc = test_support::quickstart_document();
  doc["cores"] = "1 / (cells - cells)";
  try {
    test_support::study_of(doc);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    ASSERT_FALSE(e.problems().empty());
    EXPECT_EQ(e.problems()[0].where, "/cores");
    EXPECT_NE(e.problems()[0].reason.find("must be a finite number"), std::string::npos) << e.what();
    EXPECT_NE(e.problems()[0].reason.find("grid 0"), std::string::npos) << e.what();
  }
  doc["cores"] = 0;
  EXPECT_THROW(test_support::study_of(doc), InputError);  // the schema: at least 1
}

// validate/plan list each grid's cores by the rule, before the pool's cap.
TEST(JobCores, GridListingShowsEachGridsCores) {
  auto doc = test_support::quickstart_document();
  doc["grids"] = {{"delta_star", {3.3, 2.0}}};  // 9 x 61 x 3 = 1 647 and 15 x 100 x 5 = 7 500 cells
  const auto plain = grid_listing(test_support::study_of(doc));
  EXPECT_FALSE(plain[0].cores);
  EXPECT_EQ(grid_listing_table(plain).find("cores"), std::string::npos);
  doc["cores"] = "max(1, cells / 1000)";
  const auto rows = grid_listing(test_support::study_of(doc));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].cores, 1);  // 1.647
  EXPECT_EQ(rows[1].cores, 7);  // 7.5, not capped here
  const std::string table = grid_listing_table(rows);
  EXPECT_NE(table.find("cores = max(1, cells / 1000) per job"), std::string::npos) << table;
  EXPECT_EQ(grid_listing_json(rows)[1]["cores"], 7);
}

}  // namespace
}  // namespace gridfree
