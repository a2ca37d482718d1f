// SPDX-License-Identifier: GPL-3.0-or-later
// Schema validation (core/schema_validation.h) on the embedded schemas: the
// contract's own examples pass; each kind of mistake is reported once, at
// the JSON pointer of the offending value, with a reason naming what is
// allowed.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/schema_validation.h"
#include "contract_job.h"

namespace gridfree {
namespace {

using nlohmann::json;

std::vector<Problem> job_problems(const json& doc) { return validate_against_schema(doc, "job.schema"); }

// The single problem reported, or a failure listing all of them.
Problem only_problem(const std::vector<Problem>& problems) {
  EXPECT_EQ(problems.size(), 1u) << format_problems(problems);
  return problems.empty() ? Problem{} : problems.front();
}

TEST(SchemaValidation, ContractJobIsValid) {
  EXPECT_TRUE(job_problems(test::contract_job()).empty()) << format_problems(job_problems(test::contract_job()));
  // Also under the file's own name, as a $ref would spell it.
  EXPECT_TRUE(validate_against_schema(test::contract_job(), "job.schema.json").empty());
}

TEST(SchemaValidation, UnknownKeyIsNamed) {
  json j = test::contract_job();
  j["numerics"]["relaxation"] = 0.5;
  j["case"]["gas"]["temperature_K"] = 300;
  const auto problems = job_problems(j);
  ASSERT_EQ(problems.size(), 2u) << format_problems(problems);
  const auto has = [&](const std::string& where) {
    return std::any_of(problems.begin(), problems.end(), [&](const Problem& p) {
      return p.where == where && p.reason.find("unknown key") != std::string::npos;
    });
  };
  EXPECT_TRUE(has("/numerics/relaxation"));
  EXPECT_TRUE(has("/case/gas/temperature_K"));
}

TEST(SchemaValidation, WrongTypeIsNamed) {
  json j = test::contract_job();
  j["numerics"]["max_iterations"] = "many";
  const Problem p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/numerics/max_iterations");
  EXPECT_NE(p.reason.find("expected an integer"), std::string::npos) << p.reason;
}

TEST(SchemaValidation, BadEnumListsTheChoices) {
  json j = test::contract_job();
  j["numerics"]["convection"] = "superbe";
  const Problem p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/numerics/convection");
  EXPECT_EQ(p.reason, "'superbe' is not one of fou, central, minmod, van_leer, muscl, superbee");
}

TEST(SchemaValidation, GeneratorKindAndItsParameters) {
  json j = test::contract_job();
  j["case"]["particles"]["generator"]["kind"] = "bubbling";
  Problem p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/particles/generator/kind");
  EXPECT_NE(p.reason.find("bursting_bubble, uniform_random, sscp_like"), std::string::npos);

  j = test::contract_job();
  j["case"]["particles"]["generator"]["seeds"] = 2;  // typo of a kind-specific key
  p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/particles/generator/seeds");

  j = test::contract_job();
  j["case"]["particles"]["generator"] = {{"kind", "uniform_random"}, {"seed", 1}, {"solids_fraction", 1.5}};
  p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/particles/generator/solids_fraction");
  EXPECT_EQ(p.reason, "must be < 1, got 1.5");
}

TEST(SchemaValidation, ArrayItemsAndMissingKeys) {
  json j = test::contract_job();
  j["case"]["domain_dp"][1] = -200;
  Problem p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/domain_dp/1");
  EXPECT_EQ(p.reason, "must be > 0, got -200");

  j = test::contract_job();
  j["case"]["gas"].erase("viscosity_g_cm_s");
  p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/gas/viscosity_g_cm_s");

  j = test::contract_job();
  j["numerics"]["grid"] = {{"cells", {30, 0, 10}}};
  p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/numerics/grid/cells/1");

  j = test::contract_job();
  j["numerics"]["grid"] = {{"delta_star", 1.5}};
  EXPECT_TRUE(job_problems(j).empty());
}

TEST(SchemaValidation, BoundaryForms) {
  json j = test::contract_job();
  j["case"]["boundaries"]["y_high"] = "wall";
  EXPECT_TRUE(job_problems(j).empty());
  j["case"]["boundaries"]["x"] = "open";
  const Problem p = only_problem(job_problems(j));
  EXPECT_EQ(p.where, "/case/boundaries/x");
  EXPECT_NE(p.reason.find("periodic, wall"), std::string::npos);
}

TEST(SchemaValidation, SeveralProblemsAtOnce) {
  json j = test::contract_job();
  j["numerics"]["drag"] = "stokes";
  j["case"]["particle_diameter_cm"] = "0.01";
  j["extra"] = 1;
  EXPECT_EQ(job_problems(j).size(), 3u) << format_problems(job_problems(j));
}

TEST(SchemaValidation, StudyReferencesTheJobCaseDefinition) {
  json study = {{"schema", "gridfree/study/1"},
                {"name", "bursting-bubble"},
                {"cases", {{"PC1", test::contract_job()["case"]}}},
                {"factors", {{"convection", {"superbee", "fou"}}, {"fwhm_dp", {6, 4}}, {"drag", {"bvk", "hkl"}}}},
                {"design", {{"one_at_a_time", {{"case", "PC1"}, {"convection", "superbee"}, {"fwhm_dp", 6}, {"drag", "bvk"}}}}},
                {"grids", {{"delta_star", {3.3, 2.5, 2.0, 1.5, 1.0}}}},
                {"numerics", {{"tolerances", {{"steady", 1e-5}}}}},
                {"extrapolation", {{"weights", "inverse_h"}, {"p_range", {0.5, 2.1}}}}};
  EXPECT_TRUE(validate_against_schema(study, "study.schema").empty())
      << format_problems(validate_against_schema(study, "study.schema"));

  // A case error is found through the cross-file $ref, at the study's pointer.
  study["cases"]["PC1"]["gas"]["viscosity_g_cm_s"] = 0;
  study["factors"]["drag"][1] = "hkll";
  auto problems = validate_against_schema(study, "study.schema");
  ASSERT_EQ(problems.size(), 2u) << format_problems(problems);
  std::sort(problems.begin(), problems.end(), [](const Problem& a, const Problem& b) { return a.where < b.where; });
  EXPECT_EQ(problems[0].where, "/cases/PC1/gas/viscosity_g_cm_s");
  EXPECT_EQ(problems[1].where, "/factors/drag/1");
}

TEST(SchemaValidation, UnknownSchemaIsAnInternalError) {
  EXPECT_THROW(validate_against_schema(json::object(), "no-such.schema"), std::runtime_error);
}

TEST(JsonPointer, EscapesTildeAndSlash) {
  EXPECT_EQ(json_pointer_of({"cases", "a/b~c", "0"}), "/cases/a~1b~0c/0");
}

}  // namespace
}  // namespace gridfree
