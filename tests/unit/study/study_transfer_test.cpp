// SPDX-License-Identifier: GPL-3.0-or-later
// Transfer methods as study factors (orchestrator/src/study/study_transfer.h):
// object levels reach the job documents, name the series, fill the series'
// transfer columns; contradictory or duplicate levels are refused with their
// JSON path; name levels give the same job documents (hashes) as before.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "job/job_hash.h"
#include "study/study.h"
#include "study/study_transfer.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using nlohmann::json;
using test_support::kSourceDir;
using test_support::quickstart_document;
using test_support::refusal;
using test_support::study_of;

json superbee_quickstart() {
  json doc = quickstart_document();
  doc.erase("design");
  doc["factors"] = {{"convection", {"superbee"}}};
  doc["grids"] = {{"delta_star", {2.0, 1.0}}};
  return doc;
}

TEST(StudyTransfer, ObjectLevelsReachTheJobsAndNameTheSeries) {
  json doc = superbee_quickstart();
  doc["factors"]["deposition"] = {"fm18", {{"name", "cic"}, {"pre_deposition", "trilinear"}, {"sampling", "trilinear"}},
                                  {{"pre_deposition", "centroid"}, {"sampling", "cell"}}};
  const auto ex = expand(study_of(doc));
  ASSERT_EQ(ex.series.size(), 3u);
  EXPECT_EQ(ex.series[1].deposition, "cic");
  EXPECT_NE(ex.series[1].label().find(" cic"), std::string::npos) << ex.series[1].label();
  EXPECT_EQ(ex.series[2].deposition, "pre=centroid,samp=cell");  // made from the level's fields
  ASSERT_EQ(ex.jobs.size(), 6u);
  const json& cic = ex.jobs[2].doc["numerics"]["deposition"];
  EXPECT_EQ(cic["kind"], "diffusion");
  EXPECT_EQ(cic["pre_deposition"], "trilinear");
  EXPECT_EQ(cic["sampling"], "trilinear");
  EXPECT_EQ(ex.jobs[4].doc["numerics"]["deposition"]["pre_deposition"], "centroid");
  EXPECT_EQ(ex.jobs[4].doc["numerics"]["deposition"]["sampling"], "cell");
  // The series' transfer columns, expanded by the worker's own rules.
  ASSERT_EQ(ex.transfer.size(), 3u);
  EXPECT_EQ(ex.transfer[0], (TransferColumns{"centroid", "cell", "steps", "seed", 8}));  // fm18 preset
  EXPECT_EQ(ex.transfer[1], (TransferColumns{"trilinear", "trilinear", "exact", "consistent", 0}));
  EXPECT_EQ(ex.transfer[2], (TransferColumns{"centroid", "cell", "exact", "consistent", 0}));
}

TEST(StudyTransfer, ObjectLevelsAreMergedOverTheStudysDeposition) {
  json doc = superbee_quickstart();
  doc["numerics"]["deposition"] = {{"diffusivity", "mfix"}};
  doc["factors"]["deposition"] = {json{{"name", "cic8"}, {"integration", "steps"}, {"steps", 8}}};
  const auto ex = expand(study_of(doc));
  const json& dep = ex.jobs.front().doc["numerics"]["deposition"];
  EXPECT_EQ(dep["diffusivity"], "mfix");  // from the study
  EXPECT_EQ(dep["steps"], 8);             // from the level
  EXPECT_EQ(ex.transfer.front(), (TransferColumns{"trilinear", "trilinear", "steps", "mfix", 8}));
  // A level with an integration that has no steps drops the study's step count.
  doc["numerics"]["deposition"] = {{"integration", "steps"}, {"steps", 16}};
  doc["factors"]["deposition"] = {json{{"name", "g"}, {"integration", "gaussian"}},
                                  json{{"name", "x"}, {"integration", "exact"}}};
  const auto ex2 = expand(study_of(doc));
  EXPECT_FALSE(ex2.jobs.front().doc["numerics"]["deposition"].contains("steps"));
  EXPECT_EQ(ex2.transfer[0], (TransferColumns{"trilinear", "trilinear", "gaussian", "consistent", 0}));
  EXPECT_EQ(ex2.transfer[1], (TransferColumns{"trilinear", "trilinear", "exact", "consistent", 0}));
}

TEST(StudyTransfer, NameLevelsWriteTheJobsAsBefore) {
  // The documents studies wrote before object levels existed (spelled out
  // here independently): their hashes must not change.
  json doc = superbee_quickstart();
  doc["numerics"]["deposition"] = {{"diffusivity", "seed"}};
  doc["factors"]["deposition"] = {"diffusion", "centroid", "fm18", "mfix"};
  const Study s = study_of(doc);
  const std::array<int, 3> cells{15, 100, 5};
  const json expected[] = {{{"diffusivity", "seed"}, {"kind", "diffusion"}, {"fwhm_dp", 6.0}},
                           {{"kind", "centroid"}, {"fwhm_dp", 6.0}},
                           {{"preset", "fm18"}, {"fwhm_dp", 6.0}},
                           {{"preset", "mfix"}, {"fwhm_dp", 6.0}}};
  for (std::size_t i = 0; i < 4; ++i) {
    SeriesKey key{"PC1", "superbee", 6.0, "bvk", s.factors.deposition[i]};
    json job = make_job_document(s, key, cells);
    EXPECT_EQ(job["numerics"]["deposition"], expected[i]) << key.deposition;
    json old = job;
    old["numerics"]["deposition"] = expected[i];
    EXPECT_EQ(job_hash(job), job_hash(old));
  }
}

TEST(StudyTransfer, ContradictoryLevelsAreRefusedWithTheirPath) {
  json doc = superbee_quickstart();
  doc["factors"]["deposition"] = {"fm18", {{"name", "bad"}, {"integration", "exact"}, {"steps", 4}}};
  EXPECT_NE(refusal(doc).find("/factors/deposition/1/steps"), std::string::npos) << refusal(doc);

  doc["factors"]["deposition"] = {{{"preset", "fm18"}, {"sampling", "trilinear"}}};
  EXPECT_NE(refusal(doc).find("/factors/deposition/0/sampling"), std::string::npos) << refusal(doc);

  // A field inherited from the study's numerics.deposition is blamed there.
  doc["numerics"]["deposition"] = {{"integration", "steps"}, {"steps", 16}};
  doc["factors"]["deposition"] = {{{"pre_deposition", "gaussian"}}};
  const std::string why = refusal(doc);
  EXPECT_NE(why.find("/numerics/deposition/integration"), std::string::npos) << why;
  EXPECT_NE(why.find("deposition level /factors/deposition/0"), std::string::npos) << why;
}

TEST(StudyTransfer, DuplicateTransfersAndNamesAreRefused) {
  json doc = superbee_quickstart();
  // The preset and its explicit spelling are one transfer (one job).
  doc["factors"]["deposition"] = {"fm18", {{"name", "paper"}, {"preset", "fm18"}}};
  EXPECT_NE(refusal(doc).find("/factors/deposition/1"), std::string::npos) << refusal(doc);
  EXPECT_NE(refusal(doc).find("same transfer"), std::string::npos) << refusal(doc);
  // The default transfer spelled out equals "diffusion".
  doc["factors"]["deposition"] = {"diffusion", {{"pre_deposition", "trilinear"}, {"sampling", "trilinear"}}};
  EXPECT_NE(refusal(doc).find("same transfer"), std::string::npos) << refusal(doc);
  doc["factors"]["deposition"] = {{{"name", "a"}, {"sampling", "cell"}}, {{"name", "a"}, {"pre_deposition", "centroid"}}};
  EXPECT_NE(refusal(doc).find("listed twice"), std::string::npos) << refusal(doc);
  doc["factors"]["deposition"] = {{{"name", "fm18"}, {"sampling", "cell"}}};
  EXPECT_NE(refusal(doc).find("/factors/deposition/0/name"), std::string::npos) << refusal(doc);
  doc["factors"]["deposition"] = {{{"name", "empty"}}};
  EXPECT_NE(refusal(doc).find("/factors/deposition/0"), std::string::npos) << refusal(doc);
}

TEST(StudyTransfer, OneAtATimeVariesTheTransferFromANamedBaseline) {
  json doc = superbee_quickstart();
  doc["factors"]["convection"] = {"superbee", "fou"};
  doc["factors"]["deposition"] = {{{"name", "cic"}, {"pre_deposition", "trilinear"}, {"sampling", "trilinear"}},
                                  "fm18", {{"name", "ngp-tri"}, {"pre_deposition", "centroid"}}};
  doc["design"] = {{"one_at_a_time", {{"deposition", "cic"}}}};
  const auto ex = expand(study_of(doc));
  ASSERT_EQ(ex.series.size(), 4u);  // baseline + fou + 2 other transfers
  EXPECT_EQ(ex.series[0].deposition, "cic");
  EXPECT_EQ(ex.series[1].convection, "fou");
  EXPECT_EQ(ex.series[1].deposition, "cic");
  doc["design"] = {{"one_at_a_time", {{"deposition", "nope"}}}};
  EXPECT_NE(refusal(doc).find("/design/one_at_a_time/deposition"), std::string::npos) << refusal(doc);
  // Full factorial: every convection × every transfer.
  doc.erase("design");
  EXPECT_EQ(expand(study_of(doc)).series.size(), 6u);
}

TEST(StudyTransfer, TheShippedExampleComparesThreeTransfersWithTheAlignmentCheck) {
  const auto ex = expand(parse_study(kSourceDir / "studies/transfer_alignment.json"));
  ASSERT_EQ(ex.series.size(), 3u);
  EXPECT_EQ(ex.jobs.size(), 12u);
  EXPECT_EQ(ex.alignment.size(), 3u * 2u * 3u);
  EXPECT_EQ(ex.transfer[1], (TransferColumns{"trilinear", "cell", "exact", "consistent", 0}));
}

}  // namespace
}  // namespace gridfree
