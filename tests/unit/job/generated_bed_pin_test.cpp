// SPDX-License-Identifier: GPL-3.0-or-later
// Generated beds are pinned bit for bit: a job's hash names its generator
// spec, not its particles, so a stored result stays valid only while the
// generator gives the same bed. These tests pin the SHA-256 of the particle
// array (x, y, z, d as little-endian doubles, in output order) of random
// sscp_like emulsions: the generator tests' small bed (walls; and periodic
// x and z, where centres wrap); the SSCP study's instance t1 (about 92,900
// particles) is pinned in tests/verification/job. A change to the dense
// packing that moves one bit of one particle fails them; a deliberate change
// of the beds must change the job's identity too (docs/PARTICLES.md).
#include <gtest/gtest.h>

#include <string>

#include "particles/generators.h"
#include "particle_array_sha256.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

using test_support::particle_array_sha256;

GeneratorSpec pinned_sscp(const nlohmann::json& params) { return {"sscp_like", params, "/generator"}; }

TEST(GeneratedBedPin, SmallRandomEmulsionBetweenWalls) {
  const nlohmann::json p = {{"kind", "sscp_like"}, {"seed", 3},  {"bed_height_dp", 20}, {"solids_fraction", 0.58},
                            {"bubbles", 1},        {"bubble_radius_dp", 4}};
  const ParticleSet set = generate_particles(pinned_sscp(p), test_support::sscp_bed_case());
  EXPECT_EQ(set.particles.size(), 2544u);
  EXPECT_EQ(particle_array_sha256(set), "7dd2e5c82424632f43da94698fb45d9d073632b063a689414777efe706b00c17");
}

TEST(GeneratedBedPin, SmallRandomEmulsionPeriodicInXAndZ) {
  CaseSpec c = test_support::sscp_bed_case();
  const BoundarySpec periodic{BoundaryKind::kPeriodic, 0, 0};
  c.boundaries[0] = {periodic, periodic};
  c.boundaries[2] = {periodic, periodic};
  const nlohmann::json p = {{"kind", "sscp_like"}, {"seed", 5},  {"bed_height_dp", 24}, {"solids_fraction", 0.60},
                            {"bubbles", 2},        {"bubble_radius_dp", 3}};
  const ParticleSet set = generate_particles(pinned_sscp(p), c);
  EXPECT_EQ(set.particles.size(), 3265u);
  EXPECT_EQ(particle_array_sha256(set), "dba943e847f29aedb7b7f193ac57554359f049946e9818401ff3473e4e954161");
}

}  // namespace
}  // namespace gridfree
