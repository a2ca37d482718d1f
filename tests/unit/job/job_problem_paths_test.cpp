// SPDX-License-Identifier: GPL-3.0-or-later
// A refused job's problems: the schema's and the parsers' together (a type
// error does not hide an independent range error), each once, none inside a
// value the schema could not read (core/follow_on_problems.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contract_job.h"
#include "core/follow_on_problems.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

std::vector<std::string> job_problem_paths(const json& doc) {
  std::vector<std::string> out;
  try {
    parse_job(doc, ".");
  } catch (const InputError& e) {
    for (const auto& p : e.problems()) out.push_back(p.where);
  }
  return out;
}

TEST(JobProblemPaths, AStringDomainIsOneProblem) {
  json j = test::contract_job();
  j["case"]["domain_dp"] = "thirty";
  EXPECT_EQ(job_problem_paths(j), std::vector<std::string>{"/case/domain_dp"});
}

TEST(JobProblemPaths, SchemaAndRangeProblemsAreReportedTogether) {
  json j = test::contract_job();
  j["numerics"]["convection"] = 5;                     // the schema: a string is expected
  j["case"]["probes"]["pressure_drop"]["y2_dp"] = 500;  // the parser: above L_y* = 200
  EXPECT_EQ(job_problem_paths(j),
            (std::vector<std::string>{"/numerics/convection", "/case/probes/pressure_drop/y2_dp"}));
}

TEST(FollowOnProblems, TheFirstAtAPointerAndNothingInsideAnUnreadableValue) {
  const std::vector<Problem> all = {
      {"/a/b", "expected an array, got a string"},
      {"/a/b/0", "must be > 0"},
      {"/a/bc", "must be > 0"},  // a sibling whose name starts alike is kept
      {"/a/b", "must be > 0"},
      {"/c", "required, but missing"},
      {"/c/x", "must be > 0"},
      {"/d", "must be > 0"},
  };
  const auto kept = without_follow_ons(all);
  std::vector<std::string> where;
  for (const auto& p : kept) where.push_back(p.where + ": " + p.reason);
  EXPECT_EQ(where, (std::vector<std::string>{"/a/b: expected an array, got a string", "/a/bc: must be > 0",
                                             "/c: required, but missing", "/d: must be > 0"}));
}

}  // namespace
}  // namespace gridfree
