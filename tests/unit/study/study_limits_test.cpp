// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs a study accepts only if they can be meant (docs/LIMITS.md "Study
// documents"): at least two cells along the flow, filter widths within the
// domain, a named one-at-a-time baseline, bounded name and description
// lengths (refused at once, however long).
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "quickstart_study.h"
#include "study/study.h"
#include "study_documents.h"

namespace {

using namespace gridfree;
using nlohmann::json;
using test_support::contains;
using test_support::problem_paths;
using test_support::quickstart_document;
using test_support::refusal;

TEST(StudyLimits, OneCellAlongTheFlowIsRefused) {
  json cells = quickstart_document();
  cells["grids"] = {{"cells", {{1, 1, 1}, {15, 100, 5}, {30, 200, 10}}}};
  EXPECT_TRUE(contains(problem_paths(cells), "/grids/cells/0")) << refusal(cells);
  EXPECT_NE(refusal(cells).find("flow direction"), std::string::npos) << refusal(cells);

  json coarse = quickstart_document();
  coarse["grids"] = {{"delta_star", {2.0, 1.333, 1000.0}}};  // 200 / 1000 rounds to one cell
  EXPECT_TRUE(contains(problem_paths(coarse), "/grids/delta_star/2")) << refusal(coarse);

  json two = quickstart_document();
  two["grids"] = {{"cells", {{1, 2, 1}, {15, 100, 5}, {30, 200, 10}}}};
  EXPECT_EQ(refusal(two), "(accepted)");
}

TEST(StudyLimits, FilterWiderThanTheDomainIsRefused) {
  json doc = quickstart_document();
  doc["factors"]["fwhm_dp"] = {6, 1e300};
  EXPECT_TRUE(contains(problem_paths(doc), "/factors/fwhm_dp/1")) << refusal(doc);
  doc["factors"]["fwhm_dp"] = {6, 200};  // the domain is 30 x 200 x 10 d_p
  doc.erase("design");
  EXPECT_EQ(refusal(doc), "(accepted)");
}

TEST(StudyLimits, OneAtATimeNeedsABaseline) {
  json doc = quickstart_document();
  doc["design"] = {{"one_at_a_time", json::object()}};
  EXPECT_TRUE(contains(problem_paths(doc), "/design/one_at_a_time")) << refusal(doc);
}

TEST(StudyLimits, FactorlessStudyIsOneSeriesOfTheDefaults) {
  json doc = quickstart_document();
  doc.erase("factors");
  doc.erase("design");
  EXPECT_EQ(expand(test_support::study_of(doc)).series.size(), 1u);
}

TEST(StudyLimits, NameLengthIsBounded) {
  json doc = quickstart_document();
  doc["name"] = std::string(kMaxStudyNameLength, 'a');
  EXPECT_FALSE(contains(problem_paths(doc), "/name")) << refusal(doc);
  doc["name"] = std::string(kMaxStudyNameLength + 1, 'a');
  EXPECT_TRUE(contains(problem_paths(doc), "/name")) << refusal(doc);
  EXPECT_NE(refusal(doc).find("at most 100"), std::string::npos) << refusal(doc);
}

TEST(StudyLimits, FiftyMegabyteNameOrDescriptionIsRefusedAtOnce) {
  for (const char* key : {"name", "description"}) {
    json doc = quickstart_document();
    doc[key] = std::string(50u << 20, 'a');
    const auto start = std::chrono::steady_clock::now();
    const auto paths = problem_paths(doc);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_TRUE(contains(paths, std::string("/") + key)) << key;
    EXPECT_LT(seconds, 2.0) << key;
  }
  json doc = quickstart_document();
  doc["description"] = std::string(kMaxStudyDescriptionLength, 'a');
  EXPECT_EQ(refusal(doc), "(accepted)");
}

}  // namespace
