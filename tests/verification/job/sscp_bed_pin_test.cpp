// SPDX-License-Identifier: GPL-3.0-or-later
// The bits of the SSCP study's instance t1 (studies/sscp_reduced.json: about
// 92,900 particles, 10–16 s to generate, hence a verification test, not a
// unit test): the SHA-256 of its particle array, as for the small beds of
// tests/unit/job/generated_bed_pin_test.cpp. A change to the dense packing
// that moves one bit of one particle fails it; a deliberate change of the
// beds must change the job's identity too (docs/PARTICLES.md).
#include <gtest/gtest.h>

#include "particles/generators.h"
#include "particle_array_sha256.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

TEST(GeneratedBedPin, SscpStudyInstanceT1) {
  CaseSpec c = test_support::sscp_bed_case();
  c.domain_dp = {70.639, 374.693, 23.342};
  const nlohmann::json p = {{"kind", "sscp_like"}, {"seed", 1},  {"bed_height_dp", 52.51}, {"solids_fraction", 0.58},
                            {"bubbles", 3},        {"bubble_radius_dp", 6.0}};
  const ParticleSet set = generate_particles(GeneratorSpec{"sscp_like", p, "/generator"}, c);
  EXPECT_EQ(set.particles.size(), 92952u);
  EXPECT_EQ(test_support::particle_array_sha256(set), "0cba74089990e71aa016cb2dd695f87ae03e259c3dff9af73ab085bea6691512");
}

}  // namespace
}  // namespace gridfree
