// SPDX-License-Identifier: GPL-3.0-or-later
// The studies shipped in studies/: each one parses and expands without
// duplicate jobs, and the reduced, part and single-series studies behind
// docs/REPRODUCTION.md are made of the same job documents as the full
// studies (equal job hashes), so results run for one are reused by the
// other from the same database instead of being computed again.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "study/study.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
const fs::path kStudies = fs::path(GRIDFREE_SOURCE_DIR) / "studies";

ExpandedStudy expanded(const std::string& file) { return expand(parse_study((kStudies / file).string())); }

std::set<std::string> hashes_of(const ExpandedStudy& ex) {
  std::set<std::string> out;
  for (const auto& j : ex.jobs) out.insert(j.hash);
  return out;
}

TEST(ShippedStudies, EveryStudyExpandsWithoutDuplicateJobs) {
  int seen = 0;
  for (const auto& entry : fs::directory_iterator(kStudies)) {
    if (entry.path().extension() != ".json") continue;
    ++seen;
    SCOPED_TRACE(entry.path().filename().string());
    const auto ex = expanded(entry.path().filename().string());
    EXPECT_FALSE(ex.series.empty());
    EXPECT_EQ(hashes_of(ex).size(), ex.jobs.size());
  }
  EXPECT_GE(seen, 10);
}

// Every job of `part` is a job of `whole`.
void expect_jobs_contained(const std::string& part, const std::string& whole, std::size_t expected_jobs) {
  SCOPED_TRACE(part + " in " + whole);
  const auto small = hashes_of(expanded(part));
  const auto large = hashes_of(expanded(whole));
  EXPECT_EQ(small.size(), expected_jobs);
  for (const auto& h : small) EXPECT_TRUE(large.count(h)) << h;
}

TEST(ShippedStudies, ReducedStudiesAreMadeOfTheFullStudiesJobs) {
  expect_jobs_contained("bursting_bubble_baseline.json", "bursting_bubble_paper.json", 18);
  expect_jobs_contained("bursting_bubble_medium.json", "bursting_bubble_paper.json", 12 * 13);
  expect_jobs_contained("bursting_bubble_paper_drag.json", "bursting_bubble_paper.json", 3 * 18);
  expect_jobs_contained("bursting_bubble_paper_fwhm.json", "bursting_bubble_paper.json", 3 * 18);
  expect_jobs_contained("bursting_bubble_paper_schemes.json", "bursting_bubble_paper.json", 2 * 18);
  expect_jobs_contained("bursting_bubble_paper_configurations.json", "bursting_bubble_paper.json", 3 * 18);
  expect_jobs_contained("sscp_reduced.json", "sscp_paper.json", 12 * 9);
  expect_jobs_contained("sscp_paper_t1_t2.json", "sscp_paper.json", 4 * 12);
  expect_jobs_contained("sscp_fm18_reduced.json", "sscp_fm18.json", 12 * 9);
}

TEST(ShippedStudies, TheFm18BaselineExtendsTheFm18MediumStudysBaselineSeries) {
  const auto baseline = expanded("bursting_bubble_baseline_fm18.json");
  ASSERT_EQ(baseline.series.size(), 1u);
  EXPECT_EQ(baseline.series[0].label(), "PC1 superbee fwhm6 bvk fm18");
  ASSERT_EQ(baseline.jobs.size(), 18u);
  // The medium study has the same series on the 11 coarsest grids.
  const auto medium = hashes_of(expanded("bursting_bubble_medium_fm18.json"));
  std::size_t shared = 0;
  for (const auto& j : baseline.jobs) shared += medium.count(j.hash);
  EXPECT_EQ(shared, 11u);
  for (const auto& j : baseline.jobs) EXPECT_EQ(j.doc["numerics"]["deposition"]["preset"], "fm18");
}

// The fm18 SSCP study is sscp_paper's t1 and t2 on its twelve grids with
// the paper's transfer; the alignment study re-solves t1/BVK on three of
// those grids with shifted cell counts, and its unshifted grids are the jobs
// of the two SSCP studies (default transfer and fm18), so only the shifted
// grids are new.
std::size_t shared_jobs(const ExpandedStudy& a, const std::set<std::string>& b) {
  std::size_t n = 0;
  for (const auto& j : a.jobs) n += b.count(j.hash);
  return n;
}

TEST(ShippedStudies, TheSscpAlignmentStudyReusesTheSscpStudiesGrids) {
  const auto fm18 = expanded("sscp_fm18_t1_t2.json");
  ASSERT_EQ(fm18.jobs.size(), 4u * 12u);
  for (const auto& j : fm18.jobs) EXPECT_EQ(j.doc["numerics"]["deposition"]["preset"], "fm18");
  const auto paper = hashes_of(expanded("sscp_paper.json"));
  EXPECT_EQ(shared_jobs(fm18, paper), 0u);

  const auto alignment = expanded("sscp_alignment.json");
  ASSERT_EQ(alignment.series.size(), 2u);
  EXPECT_EQ(alignment.jobs.size(), 2u * 7u);
  EXPECT_EQ(alignment.alignment.size(), 2u * 3u * 3u);
  EXPECT_EQ(shared_jobs(alignment, paper), 7u);
  EXPECT_EQ(shared_jobs(alignment, hashes_of(fm18)), 7u);
}

// The six-instance fm18 study is sscp_paper with the paper's transfer: the
// same cases, factors and grids, each job differing from its sscp_paper
// counterpart only in numerics.deposition; its t1 and t2 jobs are those of
// sscp_fm18_t1_t2, so a database holding that study runs only t3..t6.
TEST(ShippedStudies, TheSixInstanceFm18StudyIsSscpPaperWithThePapersTransfer) {
  const Study study = parse_study((kStudies / "sscp_fm18.json").string());
  const auto fm18 = expand(study);
  const auto paper = expanded("sscp_paper.json");
  ASSERT_EQ(fm18.jobs.size(), 6u * 2u * 12u);
  ASSERT_EQ(fm18.jobs.size(), paper.jobs.size());
  ASSERT_EQ(study.ensembles.size(), 1u);
  EXPECT_EQ(study.ensembles.begin()->second.size(), 6u);
  auto without_deposition = [](const ExpandedStudy& ex) {
    std::multiset<std::string> docs;
    for (const auto& j : ex.jobs) {
      auto doc = j.doc;
      doc["numerics"].erase("deposition");
      docs.insert(doc.dump());
    }
    return docs;
  };
  EXPECT_EQ(without_deposition(fm18), without_deposition(paper));
  for (const auto& j : fm18.jobs) EXPECT_EQ(j.doc["numerics"]["deposition"]["preset"], "fm18");
  EXPECT_EQ(shared_jobs(fm18, hashes_of(paper)), 0u);
  EXPECT_EQ(shared_jobs(fm18, hashes_of(expanded("sscp_fm18_t1_t2.json"))), 4u * 12u);
}

// studies/stability_remedy.json is the stability study's Re_p 300 cells
// with stall_remedy "relax_correction" and nothing else changed, so its map
// sets the option's effect beside the default's cell by cell
// (docs/SOLVER.md "The remedy on the map").
TEST(ShippedStudies, TheRemedyStudyIsTheStabilityStudysRe300CellsWithTheRemedy) {
  std::set<std::string> stability_docs;
  for (const auto& j : expanded("stability.json").jobs) stability_docs.insert(j.doc.dump());
  const auto remedy = expanded("stability_remedy.json");
  EXPECT_EQ(remedy.jobs.size(), 144u);
  for (const auto& j : remedy.jobs) {
    auto doc = j.doc;
    ASSERT_EQ(doc["numerics"].value("stall_remedy", ""), "relax_correction") << doc.dump();
    doc["numerics"].erase("stall_remedy");
    EXPECT_TRUE(stability_docs.count(doc.dump())) << "not a cell of studies/stability.json: " << doc.dump();
  }
}

// studies/stability_envelope.json measures the solver under its default
// settings (docs/SOLVER.md "The envelope under the default settings"): every
// job leaves the numerics at their defaults but for the stall window that
// ends a limit cycle, and the iteration cap, which no job reaches.
TEST(ShippedStudies, TheEnvelopeStudyRunsTheDefaultNumerics) {
  const auto ex = expanded("stability_envelope.json");
  EXPECT_EQ(ex.jobs.size(), 250u);
  const nlohmann::json defaults_deposition = {{"kind", "diffusion"}, {"fwhm_dp", 6.0}};
  for (const auto& j : ex.jobs) {
    const auto& n = j.doc["numerics"];
    for (const auto& [key, value] : n.items()) {
      const std::set<std::string> allowed = {"grid",        "convection",     "drag",        "deposition",
                                             "tolerances",  "max_iterations", "stall_window"};
      EXPECT_TRUE(allowed.count(key)) << "numerics." << key << " is not at its default";
    }
    EXPECT_EQ(n.value("convection", ""), "superbee");
    EXPECT_EQ(n.value("drag", ""), "bvk");
    EXPECT_EQ(n["deposition"], defaults_deposition) << n.dump();
    if (n.contains("tolerances")) {
      for (const auto& [key, value] : n["tolerances"].items()) {
        const double expected = key == "steady" ? 1e-5 : key == "filter" ? 1e-10 : key == "linear" ? 1e-2 : -1;
        EXPECT_EQ(value.get<double>(), expected) << "tolerances." << key;
      }
    }
    EXPECT_EQ(n.value("stall_window", 0), 200);
  }
}

}  // namespace
}  // namespace gridfree
