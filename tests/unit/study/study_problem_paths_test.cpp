// SPDX-License-Identifier: GPL-3.0-or-later
// A refused study's problems, table-driven: each independent problem once,
// at a place that is in the file (a value, or a missing key of an object
// that is), and none that follows from another (a string domain_dp has no
// elements to be > 0; a study-level deposition field that breaks two levels
// is one problem, at that field; an adaptive ladder's rungs are no array).
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "quickstart_study.h"
#include "scratch_dir.h"
#include "study/grid_listing.h"
#include "study/study.h"
#include "study_documents.h"

namespace {

using namespace gridfree;
using nlohmann::json;
using test_support::quickstart_document;
using test_support::refusal;
using test_support::study_problems;

// Whether `where` names a value of `doc`, or a key missing from an object of it.
bool is_in_file(const json& doc, const std::string& where) {
  try {
    const json::json_pointer p(where);
    if (doc.contains(p)) return true;
    return !p.empty() && doc.contains(p.parent_pointer()) && doc.at(p.parent_pointer()).is_object();
  } catch (const json::exception&) {
    return false;
  }
}

struct RefusedStudy {
  const char* name;
  std::function<void(json&)> edit;
  std::vector<std::string> problems;  // the pointers, in order
};

json adaptive_grids(double coarsest, double ratio, double finest) {
  return {{"target_rde", 0.01}, {"coarsest_delta_star", coarsest}, {"ratio", ratio}, {"finest_delta_star", finest}};
}

TEST(StudyProblemPaths, EachProblemOnceInTheFileWithoutFollowOns) {
  const std::vector<RefusedStudy> table = {
      {"a string domain", [](json& d) { d["cases"]["PC1"]["domain_dp"] = "thirty"; }, {"/cases/PC1/domain_dp"}},
      {"a string gas", [](json& d) { d["cases"]["PC1"]["gas"] = "air"; }, {"/cases/PC1/gas"}},
      {"a string diameter", [](json& d) { d["cases"]["PC1"]["particle_diameter_cm"] = "small"; },
       {"/cases/PC1/particle_diameter_cm"}},
      {"a string probe",
       [](json& d) { d["cases"]["PC1"]["probes"]["pressure_drop"]["y2_dp"] = "top"; },
       {"/cases/PC1/probes/pressure_drop/y2_dp"}},
      {"three independent problems",
       [](json& d) {
         d["cases"]["PC1"]["domain_dp"] = "thirty";
         d["factors"]["drag"] = {"bvk", "nope"};
         d["grids"]["delta_star"][0] = -1;
       },
       {"/cases/PC1/domain_dp", "/factors/drag/1", "/grids/delta_star/0"}},
      {"a bad level beside a one-cell grid (reported together)",
       [](json& d) {
         d["factors"]["drag"] = {"bvk", "nope"};
         d["grids"] = {{"delta_star", {300.0, 2.0, 1.333}}};
       },
       {"/factors/drag/1", "/grids/delta_star/0"}},
      {"a study deposition field a name level cannot take",
       [](json& d) {
         d["factors"]["deposition"] = {"diffusion"};
         d["numerics"]["deposition"] = {{"steps", 4}};
       },
       {"/numerics/deposition/steps"}},
      {"a study deposition field two levels cannot take",
       [](json& d) {
         d["factors"]["deposition"] = {"diffusion", {{"name", "cic"}, {"sampling", "cell"}}};
         d["numerics"]["deposition"] = {{"truncation_sigmas", 3}};
       },
       {"/numerics/deposition/truncation_sigmas"}},
      {"a level's own field", [](json& d) { d["factors"]["deposition"] = {{{"integration", "exact"}, {"steps", 4}}}; },
       {"/factors/deposition/0/steps"}},
      {"a pointer after a refused level",
       [](json& d) { d["factors"]["deposition"] = {"bogus", {{"integration", "exact"}, {"steps", 4}}}; },
       {"/factors/deposition/0", "/factors/deposition/1/steps"}},
      {"an adaptive ladder too fine", [](json& d) { d["grids"] = adaptive_grids(0.001, 1.25, 0.0001); },
       {"/grids/finest_delta_star"}},
      {"an adaptive ladder too coarse", [](json& d) { d["grids"] = adaptive_grids(150, 1.5, 10); },
       {"/grids/coarsest_delta_star"}},
      {"a declared order of 0", [](json& d) { d["extrapolation"] = {{"expected_order", 0}}; },
       {"/extrapolation/expected_order"}},
      {"a declared order that is text", [](json& d) { d["extrapolation"] = {{"expected_order", "second"}}; },
       {"/extrapolation/expected_order"}},
  };
  for (const auto& row : table) {
    json doc = quickstart_document();
    row.edit(doc);
    std::vector<std::string> got;
    for (const auto& p : study_problems(doc)) {
      got.push_back(p.where);
      EXPECT_TRUE(is_in_file(doc, p.where)) << row.name << ": " << p.where << " is not in the file";
    }
    EXPECT_EQ(got, row.problems) << row.name << ":\n" << refusal(doc);
  }
}

TEST(StudyProblemPaths, AParticleFileWithAParticleOutsideTheDomainIsRefusedAtValidation) {
  const auto dir = test_support::fresh_scratch_dir("study_problem_paths", "particle_file");
  // PC1's domain is 30 x 200 x 10 d_p of 0.01 cm: 0.3 x 2 x 0.1 cm.
  std::ofstream(dir / "inside.csv") << "x,y,z,d\n0.15,0.5,0.05,0.01\n0.15,0.6,0.05,0.01\n";
  std::ofstream(dir / "outside.csv") << "x,y,z,d\n0.15,0.5,0.05,0.01\n0.15,2.5,0.05,0.01\n";
  json doc = quickstart_document();
  doc["cases"]["PC1"]["particles"] = {{"file", (dir / "inside.csv").string()}, {"format", "csv"}};
  EXPECT_EQ(refusal(doc), "(accepted)");
  doc["cases"]["PC1"]["particles"]["file"] = (dir / "outside.csv").string();
  const auto problems = study_problems(doc);
  ASSERT_EQ(problems.size(), 1u) << refusal(doc);
  EXPECT_EQ(problems[0].where, "/cases/PC1/particles/file");
  EXPECT_NE(problems[0].reason.find("outside the domain"), std::string::npos) << problems[0].reason;
  EXPECT_NE(problems[0].reason.find("outside.csv:3"), std::string::npos) << problems[0].reason;
}

TEST(StudyProblemPaths, TwoLevelsBrokenByOneStudyFieldAreNamedInItsOneProblem) {
  json doc = quickstart_document();
  doc["factors"]["deposition"] = {"diffusion", {{"name", "cic"}, {"sampling", "cell"}}};
  doc["numerics"]["deposition"] = {{"truncation_sigmas", 3}};
  const auto problems = study_problems(doc);
  ASSERT_EQ(problems.size(), 1u) << refusal(doc);
  EXPECT_NE(problems[0].reason.find("levels /factors/deposition/0, /factors/deposition/1"), std::string::npos)
      << problems[0].reason;
}

TEST(StudyProblemPaths, AnAdaptiveLaddersGridsAreNamedAsRungs) {
  json doc = quickstart_document();
  doc["grids"] = adaptive_grids(2, 1.25, 0.5);
  const auto rows = grid_listing(test_support::study_of(doc));
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0].pointer, "/grids ladder rung 1");
  for (const auto& w : neighbour_warnings(rows, 10.0)) EXPECT_EQ(w.find("/grids/delta_star"), std::string::npos) << w;
  EXPECT_FALSE(neighbour_warnings(rows, 10.0).empty());
}

}  // namespace
