// SPDX-License-Identifier: GPL-3.0-or-later
// The "ensembles" field of a study (orchestrator/src/study/study_ensembles.h):
// parsed into Study::ensembles; unknown cases, a case in two ensembles, a
// case listed twice, an ensemble of one, a bad name and instances with
// different domains are refused with their JSON pointers; the shipped SSCP
// study declares its six instances.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/input_error.h"
#include "study/study.h"
#include "quickstart_study.h"
#include "study_documents.h"

namespace gridfree {
namespace {

using nlohmann::json;
using test_support::kSourceDir;
using test_support::quickstart_document;
using test_support::study_of;
using test_support::study_problems;

// quickstart with three seeded instances of PC1 (PC1, PC2, PC3) and a PC4 of another domain.
json three_instances() {
  json doc = quickstart_document();
  doc["cases"]["PC2"] = {{"extends", "PC1"}, {"particles", {{"generator", {{"seed", 2}}}}}};
  doc["cases"]["PC3"] = {{"extends", "PC1"}, {"particles", {{"generator", {{"seed", 3}}}}}};
  doc["cases"]["PC4"] = {{"extends", "PC1"}, {"domain_dp", {31, 200, 10}}};
  doc["ensembles"] = {{"bubble", {"PC1", "PC2", "PC3"}}};
  return doc;
}

bool has_problem(const json& doc, const std::string& where, const std::string& words) {
  const auto all = study_problems(doc);
  return std::any_of(all.begin(), all.end(), [&](const Problem& p) {
    return p.where == where && p.reason.find(words) != std::string::npos;
  });
}

TEST(StudyEnsembles, ParsedInListedOrder) {
  const Study s = study_of(three_instances());
  ASSERT_EQ(s.ensembles.size(), 1u);
  EXPECT_EQ(s.ensembles.at("bubble"), (std::vector<std::string>{"PC1", "PC2", "PC3"}));
  EXPECT_EQ(ensemble_of(s.ensembles, "PC2"), "bubble");
  EXPECT_EQ(ensemble_of(s.ensembles, "PC4"), "");
}

TEST(StudyEnsembles, AbsentMeansNone) {
  json doc = three_instances();
  doc.erase("ensembles");
  EXPECT_TRUE(study_of(doc).ensembles.empty());
}

TEST(StudyEnsembles, UnknownCaseNamedByPointer) {
  json doc = three_instances();
  doc["ensembles"]["bubble"].push_back("PC9");
  EXPECT_TRUE(has_problem(doc, "/ensembles/bubble/3", "unknown case 'PC9'"));
}

TEST(StudyEnsembles, CaseInTwoEnsemblesRefused) {
  json doc = three_instances();
  doc["ensembles"]["zzz"] = {"PC3", "PC1"};
  // Ensembles are read by name: "bubble" first, so "zzz"'s first entry is the repeat.
  EXPECT_TRUE(has_problem(doc, "/ensembles/zzz/0", "already in ensemble 'bubble'"));
}

TEST(StudyEnsembles, CaseListedTwiceRefused) {
  json doc = three_instances();
  doc["ensembles"]["bubble"] = {"PC1", "PC2", "PC1"};
  EXPECT_FALSE(study_problems(doc).empty());
  // The schema's uniqueItems or our own check: either names the ensemble's array or the entry.
  const auto all = study_problems(doc);
  EXPECT_TRUE(std::any_of(all.begin(), all.end(),
                          [](const Problem& p) { return p.where.rfind("/ensembles/bubble", 0) == 0; }));
}

TEST(StudyEnsembles, EnsembleOfOneRefused) {
  json doc = three_instances();
  doc["ensembles"]["bubble"] = {"PC1"};
  const auto all = study_problems(doc);
  ASSERT_FALSE(all.empty());
  EXPECT_TRUE(std::any_of(all.begin(), all.end(), [](const Problem& p) { return p.where == "/ensembles/bubble"; }));
}

TEST(StudyEnsembles, BadNameAndWrongTypesRefused) {
  json doc = three_instances();
  doc["ensembles"] = {{"a b", {"PC1", "PC2"}}};
  EXPECT_TRUE(has_problem(doc, "/ensembles/a b", "use letters"));
  doc["ensembles"] = json::array({"PC1"});
  EXPECT_FALSE(study_problems(doc).empty());
  doc["ensembles"] = {{"bubble", {"PC1", 3}}};
  EXPECT_FALSE(study_problems(doc).empty());
}

TEST(StudyEnsembles, InstancesShareTheDomain) {
  json doc = three_instances();
  doc["ensembles"]["bubble"] = {"PC1", "PC4"};
  EXPECT_TRUE(has_problem(doc, "/ensembles/bubble/1", "another domain_dp"));
}

TEST(StudyEnsembles, SscpStudyDeclaresSixInstances) {
  const Study s = parse_study(kSourceDir / "studies/sscp_paper.json");
  ASSERT_EQ(s.ensembles.count("sscp"), 1u);
  EXPECT_EQ(s.ensembles.at("sscp"), (std::vector<std::string>{"t1", "t2", "t3", "t4", "t5", "t6"}));
}

}  // namespace
}  // namespace gridfree
