// SPDX-License-Identifier: GPL-3.0-or-later
// A study's "numerics" reach every job it expands to (tolerances,
// max_iterations, stall_window, deposition.diffusivity), and its factor levels set the
// job's convection, drag and deposition: what each job then computes from
// them is checked field by field in tests/verification/flow/field_effect_test.cpp.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "study/study.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using nlohmann::json;
using test_support::quickstart_document;
using test_support::study_of;

TEST(StudyNumerics, CopiedIntoEveryJob) {
  json doc = quickstart_document();
  doc["numerics"] = {{"tolerances", {{"linear", 1e-4}, {"filter", 1e-9}, {"steady", 1e-6}}},
                     {"max_iterations", 1234},
                     {"stall_window", 150},
                     {"deposition", {{"diffusivity", "mfix"}}}};
  doc["factors"] = {{"convection", {"fou"}}, {"fwhm_dp", {8}}, {"drag", {"hkl"}}};
  doc.erase("design");
  const auto ex = expand(study_of(doc));
  ASSERT_FALSE(ex.jobs.empty());
  for (const auto& j : ex.jobs) {
    const json& n = j.doc["numerics"];
    EXPECT_EQ(n["tolerances"]["linear"], 1e-4);
    EXPECT_EQ(n["tolerances"]["filter"], 1e-9);
    EXPECT_EQ(n["tolerances"]["steady"], 1e-6);
    EXPECT_EQ(n["max_iterations"], 1234);
    EXPECT_EQ(n["stall_window"], 150);
    EXPECT_EQ(n["deposition"]["diffusivity"], "mfix");
    EXPECT_EQ(n["deposition"]["fwhm_dp"], 8);
    EXPECT_EQ(n["convection"], "fou");
    EXPECT_EQ(n["drag"], "hkl");
  }
}

TEST(StudyNumerics, OutOfRangeValuesAreRefusedWithTheirPath) {
  json doc = quickstart_document();
  doc["numerics"]["tolerances"]["linear"] = 2.0;
  doc["numerics"]["stall_window"] = -5;
  doc["timeout_s"] = -1;
  try {
    study_of(doc);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/numerics/tolerances/linear"), std::string::npos) << what;
    EXPECT_NE(what.find("/timeout_s"), std::string::npos) << what;
    EXPECT_NE(what.find("/numerics/stall_window"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace gridfree
