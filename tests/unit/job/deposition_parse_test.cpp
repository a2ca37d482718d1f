// SPDX-License-Identifier: GPL-3.0-or-later
// numerics.deposition (job/deposition_parse.cpp): presets expand to the
// explicit fields, defaults are the default transfer, and every
// contradictory combination is refused with the field's JSON pointer.
#include <gtest/gtest.h>

#include <algorithm>

#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

std::vector<Problem> deposition_problems(const json& dep) {
  ProblemList problems;
  parse_deposition(dep, "/numerics/deposition", problems);
  return problems.problems();
}

bool refused_at(const json& dep, const std::string& where) {
  const auto p = deposition_problems(dep);
  return std::any_of(p.begin(), p.end(), [&](const Problem& q) { return q.where == where; });
}

TEST(DepositionParse, PresetsExpandToThePapersAndMfixsMethods) {
  ProblemList problems;
  const DepositionSpec fm18 = parse_deposition({{"preset", "fm18"}, {"fwhm_dp", 6}}, "/d", problems);
  EXPECT_EQ(fm18.pre_deposition, PreDeposition::kCentroid);
  EXPECT_EQ(fm18.sampling, Sampling::kCell);
  EXPECT_EQ(fm18.diffusivity, FilterDiffusivity::kSeed);
  EXPECT_EQ(fm18.integration, FilterIntegration::kSteps);
  EXPECT_EQ(fm18.steps, 8);
  const DepositionSpec mfix = parse_deposition({{"preset", "mfix"}, {"fwhm_dp", 6}}, "/d", problems);
  EXPECT_EQ(mfix.diffusivity, FilterDiffusivity::kMfix);
  EXPECT_EQ(mfix.steps, 5);
  EXPECT_TRUE(problems.empty());
}

TEST(DepositionParse, DefaultsAreTheDefaultTransfer) {
  ProblemList problems;
  const DepositionSpec d = parse_deposition({{"kind", "diffusion"}, {"fwhm_dp", 6}}, "/d", problems);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(d.pre_deposition, PreDeposition::kTrilinear);
  EXPECT_EQ(d.sampling, Sampling::kTrilinear);
  EXPECT_EQ(d.diffusivity, FilterDiffusivity::kConsistent);
  EXPECT_EQ(d.integration, FilterIntegration::kExact);
  const json j = deposition_json(d, {});
  EXPECT_FALSE(j.contains("steps"));  // exact integration has none
}

TEST(DepositionParse, ContradictionsAreRefusedWithTheirField) {
  const std::string at = "/numerics/deposition/";
  EXPECT_TRUE(refused_at({{"kind", "centroid"}, {"sampling", "trilinear"}}, at + "sampling"));
  EXPECT_TRUE(refused_at({{"kind", "centroid"}, {"pre_deposition", "trilinear"}}, at + "pre_deposition"));
  EXPECT_TRUE(refused_at({{"preset", "fm18"}, {"fwhm_dp", 6}, {"steps", 4}}, at + "steps"));
  EXPECT_TRUE(refused_at({{"preset", "fm18"}, {"fwhm_dp", 6}, {"kind", "centroid"}}, at + "kind"));
  EXPECT_TRUE(refused_at({{"preset", "paper"}, {"fwhm_dp", 6}}, at + "preset"));
  EXPECT_TRUE(refused_at({{"preset", "fm18"}}, at + "fwhm_dp"));
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"steps", 4}}, at + "steps"));  // exact by default
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"pre_deposition", "gaussian"}, {"integration", "exact"}},
                         at + "integration"));
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"pre_deposition", "gaussian"}, {"sampling", "trilinear"}},
                         at + "sampling"));
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"sampling", "gaussian"}}, at + "sampling"));
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"truncation_sigmas", 4}}, at + "truncation_sigmas"));
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"integration", "steps"}, {"steps", 0}}, at + "steps"));
  EXPECT_TRUE(
      deposition_problems({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"integration", "steps"}, {"steps", 3}}).empty());
  EXPECT_TRUE(deposition_problems({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"pre_deposition", "gaussian"}}).empty());
}

TEST(DepositionParse, GaussianIntegrationIsAcceptedRecordedAndHasNoSteps) {
  ProblemList problems;
  const DepositionSpec d =
      parse_deposition({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"integration", "gaussian"}}, "/d", problems);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(d.integration, FilterIntegration::kGaussian);
  const json j = deposition_json(d, {});
  EXPECT_EQ(j.at("integration"), "gaussian");
  EXPECT_FALSE(j.contains("steps"));
  const std::string at = "/numerics/deposition/";
  EXPECT_TRUE(refused_at({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"integration", "gaussian"}, {"steps", 8}}, at + "steps"));
  const auto p = deposition_problems({{"kind", "diffusion"}, {"fwhm_dp", 6}, {"integration", "heat"}});
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].where, at + "integration");
  EXPECT_NE(p[0].reason.find("steps, exact, gaussian"), std::string::npos) << p[0].reason;
}

}  // namespace
}  // namespace gridfree
