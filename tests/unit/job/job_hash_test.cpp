// SPDX-License-Identifier: GPL-3.0-or-later
// Canonical JSON and the job hash: key order and integer/float spelling do
// not matter; any change of a value does.
#include <gtest/gtest.h>

#include "core/version.h"
#include "job/job_hash.h"
#include "job/job_normalise.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

json example_job() {
  return json::parse(R"({"schema": "gridfree/job/1",
    "case": {"domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01, "name": "PC1",
             "particles": {"generator": {"kind": "bursting_bubble", "seed": 1}}},
    "numerics": {"grid": {"cells": [30, 200, 10]}, "convection": "superbee", "drag": "bvk",
                 "deposition": {"kind": "diffusion", "fwhm_dp": 6}}})");
}

TEST(CanonicalJson, SortsKeysAndDropsWhitespace) {
  const json a = json::parse(R"({"b": 1, "a": {"d": [1, 2], "c": "x"}})");
  EXPECT_EQ(canonical_json(a), R"({"a":{"c":"x","d":[1,2]},"b":1})");
}

TEST(CanonicalJson, NumbersAsShortestDoubles) {
  EXPECT_EQ(canonical_json(json::parse("[20, 20.0, 2e1, 0.1, 1e-8, -0.0, 0]")), "[20,20,20,0.1,1e-08,0,0]");
  EXPECT_EQ(canonical_json(json::parse(R"({"s": "a\"b", "t": true, "n": null})")), R"({"n":null,"s":"a\"b","t":true})");
}

TEST(JobHashDefinition, IntegerAndFloatSpellingsHashAlike) {
  json a = example_job();
  json b = example_job();
  b["numerics"]["deposition"]["fwhm_dp"] = 6.0;
  b["case"]["domain_dp"] = json::parse("[30.0, 200.0, 1e1]");
  EXPECT_EQ(job_hash(a), job_hash(b));
  // Key order in the source text does not matter either.
  const json c = json::parse(R"({"numerics": {"drag": "bvk", "convection": "superbee",
      "deposition": {"fwhm_dp": 6, "kind": "diffusion"}, "grid": {"cells": [30, 200, 10]}},
    "case": {"name": "PC1", "particle_diameter_cm": 0.01, "domain_dp": [30, 200, 10],
             "particles": {"generator": {"seed": 1, "kind": "bursting_bubble"}}},
    "schema": "gridfree/job/1"})");
  EXPECT_EQ(job_hash(a), job_hash(c));
}

TEST(JobHashDefinition, AnyValueChangeChangesTheHash) {
  const std::string base = job_hash(example_job());
  EXPECT_EQ(base.size(), 64u);
  const auto changed = [&](auto edit) {
    json j = example_job();
    edit(j);
    return job_hash(j);
  };
  EXPECT_NE(base, changed([](json& j) { j["case"]["particles"]["generator"]["seed"] = 2; }));
  EXPECT_NE(base, changed([](json& j) { j["numerics"]["grid"]["cells"][1] = 201; }));
  EXPECT_NE(base, changed([](json& j) { j["numerics"]["convection"] = "fou"; }));
  EXPECT_NE(base, changed([](json& j) { j["case"]["particle_diameter_cm"] = 0.0100000001; }));
  EXPECT_NE(base, changed([](json& j) { j["numerics"]["tolerances"] = {{"steady", 1e-6}}; }));
}

TEST(JobHashDefinition, IsShaOfCanonicalTextAndSolverVersion) {
  // The normalised document (defaults written in, numerics.deposition
  // expanded) is hashed; a document that is its own normalised form hashes
  // its own canonical text.
  const json j = normalised_job(example_job());
  EXPECT_EQ(normalised_job(j), j);
  EXPECT_EQ(job_hash(example_job()), sha256_hex(canonical_json(j) + "\n" + kSolverVersion));
  EXPECT_EQ(job_hash(j), job_hash(example_job()));
}

TEST(JobHashDefinition, APresetAndItsExplicitSpellingAreOneJob) {
  json preset = example_job(), explicit_ = example_job(), other = example_job();
  preset["numerics"]["deposition"] = {{"preset", "fm18"}, {"fwhm_dp", 6}};
  explicit_["numerics"]["deposition"] = {{"kind", "diffusion"},     {"fwhm_dp", 6},   {"pre_deposition", "centroid"},
                                         {"sampling", "cell"},      {"diffusivity", "seed"},
                                         {"integration", "steps"},  {"steps", 8}};
  other["numerics"]["deposition"] = {{"preset", "mfix"}, {"fwhm_dp", 6}};
  EXPECT_EQ(job_hash(preset), job_hash(explicit_));
  EXPECT_NE(job_hash(preset), job_hash(other));
  // An omitted default and the default given are one job too.
  json defaults = example_job(), spelled = example_job();
  defaults["numerics"]["deposition"] = {{"kind", "diffusion"}, {"fwhm_dp", 6}};
  spelled["numerics"]["deposition"] = {{"kind", "diffusion"},   {"fwhm_dp", 6},          {"pre_deposition", "trilinear"},
                                       {"sampling", "trilinear"}, {"diffusivity", "consistent"}, {"integration", "exact"}};
  EXPECT_EQ(job_hash(defaults), job_hash(spelled));
  EXPECT_NE(job_hash(defaults), job_hash(preset));
}

}  // namespace
TEST(JobHashDefinition, SscpLikeEmulsionDefaultIsHashedAsRandom) {
  json omitted = example_job();
  omitted["case"]["particles"] = {{"generator", {{"kind", "sscp_like"}, {"seed", 1}, {"bed_height_dp", 20},
                                                 {"solids_fraction", 0.58}, {"bubbles", 0}, {"bubble_radius_dp", 3}}}};
  json random = omitted, lattice = omitted;
  random["case"]["particles"]["generator"]["emulsion"] = "random";
  lattice["case"]["particles"]["generator"]["emulsion"] = "lattice";
  EXPECT_EQ(job_hash(omitted), job_hash(random));
  EXPECT_NE(job_hash(omitted), job_hash(lattice));
  // The text hashed before the random emulsion (then a lattice bed) is not the new job's.
  json before = omitted;
  ProblemList problems;
  before["numerics"]["deposition"] =
      deposition_json(parse_deposition(before["numerics"]["deposition"], "/numerics/deposition", problems),
                      before["numerics"]["deposition"]);
  ASSERT_TRUE(problems.empty());
  EXPECT_NE(job_hash(omitted), sha256_hex(canonical_json(before) + "\n" + kSolverVersion));
}

}  // namespace gridfree
