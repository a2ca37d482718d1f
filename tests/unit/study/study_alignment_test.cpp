// SPDX-License-Identifier: GPL-3.0-or-later
// The alignment check as a study option (orchestrator/src/study/study_alignment.h):
// variant jobs per series and checked grid, with their cell offsets, linked
// to the grid's own job and kept out of the series' jobs; bad options refused
// with their JSON path; a study without the option expands as before.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "job/job_hash.h"
#include "study/study.h"
#include "study/study_alignment.h"
#include "study/study_plan.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using nlohmann::json;
using test_support::quickstart_document;
using test_support::refusal;
using test_support::study_of;

json two_schemes_quickstart() {
  json doc = quickstart_document();
  doc.erase("design");
  doc["factors"] = {{"convection", {"superbee", "fou"}}};
  doc["grids"] = {{"delta_star", {2.0, 1.0, 0.8}}};
  return doc;
}

TEST(StudyAlignment, VariantsOfTheListedGridsForEverySeries) {
  json doc = two_schemes_quickstart();
  const auto plain = expand(study_of(doc));
  doc["alignment"] = {{"delta_star", {2.0, 0.8}}, {"ny_offsets", {1, 2, 3}}, {"nx_offsets", {0, 1}}};
  const auto ex = expand(study_of(doc));
  // The series' own jobs are unchanged by the option.
  ASSERT_EQ(ex.jobs.size(), plain.jobs.size());
  for (std::size_t i = 0; i < ex.jobs.size(); ++i) EXPECT_EQ(ex.jobs[i].hash, plain.jobs[i].hash);
  // 2 series × 2 grids × (3 × 2 − 0 zero combinations: ny never 0) variants.
  ASSERT_EQ(ex.alignment.size(), 2u * 2u * 6u);
  for (const auto& a : ex.alignment) {
    const StudyJob* base = nullptr;
    for (const auto& j : ex.jobs)
      if (j.series == a.series && j.grid == a.grid) base = &j;
    ASSERT_NE(base, nullptr);
    EXPECT_EQ(a.base_hash, base->hash);
    EXPECT_TRUE(a.grid == 0 || a.grid == 2);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.cells[k], base->cells[k] + a.offsets[k]);
    EXPECT_GE(a.offsets[1], 1);
    const auto& c = a.doc["numerics"]["grid"]["cells"];
    EXPECT_EQ(c[1].get<int>(), a.cells[1]);
    EXPECT_EQ(a.hash, job_hash(a.doc));
    // Same numerics as the grid's own job but for the cells.
    json other = a.doc;
    other["numerics"]["grid"] = base->doc["numerics"]["grid"];
    EXPECT_EQ(other, base->doc);
  }
}

TEST(StudyAlignment, AllGridsWhenNoneListedAndZeroCombinationLeftOut) {
  json doc = two_schemes_quickstart();
  doc["factors"]["convection"] = {"superbee"};
  doc["alignment"] = {{"ny_offsets", {-1, 0, 1}}};
  const auto ex = expand(study_of(doc));
  EXPECT_EQ(ex.alignment.size(), 3u * 2u);  // 3 grids × offsets −1, +1
  EXPECT_TRUE(expand(study_of(two_schemes_quickstart())).alignment.empty());  // default off
}

TEST(StudyAlignment, ThePlanCountsTheVariants) {
  json doc = two_schemes_quickstart();
  const Study plain_study = study_of(doc);
  const Plan plain = make_plan(plain_study, expand(plain_study), 1, 1);
  doc["alignment"] = {{"delta_star", {2.0}}, {"ny_offsets", {1}}};
  const Study s = study_of(doc);
  const ExpandedStudy ex = expand(s);
  const Plan plan = make_plan(s, ex, 1, 1);
  EXPECT_EQ(plan.jobs, plain.jobs + 2);  // one variant per series
  EXPECT_EQ(plan.rows[0].alignment_jobs, 1u);
  EXPECT_EQ(plan.rows[0].grids, plain.rows[0].grids);
  EXPECT_EQ(plan.cells - plain.cells, 2u * static_cast<std::uint64_t>(ex.alignment[0].cells[0]) *
                                          ex.alignment[0].cells[1] * ex.alignment[0].cells[2]);
  EXPECT_GT(plan.seconds, plain.seconds);
}

TEST(StudyAlignment, BadOptionsAreRefusedWithTheirPath) {
  json doc = two_schemes_quickstart();
  doc["alignment"] = {{"delta_star", {1.5}}, {"ny_offsets", {1}}};
  EXPECT_NE(refusal(doc).find("/alignment/delta_star/0"), std::string::npos) << refusal(doc);
  doc["alignment"] = {{"ny_offsets", {0}}};
  EXPECT_NE(refusal(doc).find("/alignment"), std::string::npos) << refusal(doc);
  EXPECT_NE(refusal(doc).find("non-zero offset"), std::string::npos) << refusal(doc);
  doc["alignment"] = {{"cells", {{15, 100, 5}}}, {"ny_offsets", {1}}};
  EXPECT_NE(refusal(doc).find("/alignment/cells"), std::string::npos) << refusal(doc);
  doc["alignment"] = {{"nz_offsets", {-5}}};  // Δ* 2 has 5 cells in z
  EXPECT_NE(refusal(doc).find("/alignment/nz_offsets"), std::string::npos) << refusal(doc);
  doc["alignment"] = {{"ny_offsets", {1}}, {"shifts", {0.5}}};
  EXPECT_NE(refusal(doc).find("/alignment"), std::string::npos) << refusal(doc);
}

}  // namespace
}  // namespace gridfree
