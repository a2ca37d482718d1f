// SPDX-License-Identifier: GPL-3.0-or-later
// The bursting-bubble configuration (PHYSICS.md §6) on the paper's domain.
// Region counts are recomputed here from the geometry; the solids fraction
// of each region is measured by classifying every particle centre (not from
// the generator's own report); overlaps are checked by an O(N²) loop.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "particle_checks.h"
#include "particles/generators.h"
#include "particles/particle_io.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;
constexpr double kD = 0.01;  // cm, the paper's particle

CaseSpec paper_case() {
  CaseSpec c;
  c.domain_dp = {30, 200, 10};
  c.particle_diameter_cm = kD;
  const BoundarySpec periodic{BoundaryKind::kPeriodic, 0, 0};
  c.boundaries[0] = {periodic, periodic};
  c.boundaries[2] = {periodic, periodic};
  c.boundaries[1] = {BoundarySpec{BoundaryKind::kMassInflow, 20, 0}, BoundarySpec{BoundaryKind::kPressureOutflow, 0, 0}};
  return c;
}

GeneratorSpec bubble(std::uint64_t seed) {
  return {"bursting_bubble", {{"kind", "bursting_bubble"}, {"seed", seed}}, "/generator"};
}

std::string csv_bytes(const ParticleSet& set, const std::string& name) {
  const fs::path file = fs::temp_directory_path() / (std::to_string(::getpid()) + "_" + name);
  write_csv(file, set);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  fs::remove(file);
  return s.str();
}

TEST(BurstingBubbleGenerator, CountsAndFractionsPerRegion) {
  const GeneratedParticles out = generate_particles_with_report(bubble(1), paper_case());
  // Volumes in d³: dense box 30·28·10 minus the sphere 4/3 π 5³; freeboard 30·22·10.
  const double vp = std::numbers::pi / 6;  // V_p / d³
  const double v_sphere = 4.0 / 3.0 * std::numbers::pi * 125;
  const double v_dense = 30 * 28 * 10 - v_sphere, v_free = 30 * 22 * 10;
  EXPECT_EQ(std::lround(0.30 * v_dense / vp), 4513);
  EXPECT_EQ(std::lround(0.01 * v_sphere / vp), 10);
  EXPECT_EQ(std::lround(0.01 * v_free / vp), 126);

  std::size_t dense = 0, in_bubble = 0, free = 0, above = 0;
  for (const Particle& p : out.set.particles) {
    const double x = p.x / kD, y = p.y / kD, z = p.z / kD;
    const double r2 = (x - 15) * (x - 15) + (y - 22) * (y - 22) + (z - 5) * (z - 5);
    if (y >= 50) ++above;
    else if (y >= 28) ++free;
    else if (r2 < 25) ++in_bubble;
    else ++dense;
    EXPECT_DOUBLE_EQ(p.d, kD);
  }
  EXPECT_EQ(out.set.particles.size(), 4649u);
  EXPECT_EQ(dense, 4513u);
  EXPECT_EQ(in_bubble, 10u);
  EXPECT_EQ(free, 126u);
  EXPECT_EQ(above, 0u);
  // ε_s per region from the measured counts: within ±0.005 (absolute) of
  // the target. Rounding one particle moves ε_s by V_p/V_region ≤ 0.05 % in
  // the dense bed and ≤ 0.1 % in the bubble, so 0.005 leaves room only for
  // a wrong region.
  EXPECT_NEAR(dense * vp / v_dense, 0.30, 0.005);
  EXPECT_NEAR(in_bubble * vp / v_sphere, 0.01, 0.005);
  EXPECT_NEAR(free * vp / v_free, 0.01, 0.005);
  // The report agrees with the classification.
  ASSERT_GE(out.regions.size(), 3u);
  EXPECT_EQ(out.regions[0].count, dense);
  EXPECT_EQ(out.regions[1].count, in_bubble);
  EXPECT_EQ(out.regions[2].count, free);
}

TEST(BurstingBubbleGenerator, NoOverlapAndInsideTheDomain) {
  const CaseSpec c = paper_case();
  const ParticleSet set = generate_particles(bubble(2), c);
  EXPECT_EQ(test::count_overlaps(set.particles, c.domain_cm(), {true, false, true}), 0u);
  EXPECT_EQ(test::count_outside(set.particles, c.domain_cm(), {true, false, true}), 0u);
  // The library's own check agrees, with no tolerance.
  EXPECT_NO_THROW(check_particles(set, c, {0.0, 20}));
}

TEST(BurstingBubbleGenerator, SameSeedSameBytesOtherSeedOtherBed) {
  const CaseSpec c = paper_case();
  const std::string a = csv_bytes(generate_particles(bubble(1), c), "gridfree_bb_a.csv");
  const std::string b = csv_bytes(generate_particles(bubble(1), c), "gridfree_bb_b.csv");
  const std::string other = csv_bytes(generate_particles(bubble(3), c), "gridfree_bb_c.csv");
  EXPECT_EQ(a, b);
  EXPECT_NE(a, other);
  EXPECT_EQ(a.rfind("x,y,z,d\n", 0), 0u);
}

TEST(BurstingBubbleGenerator, DomainTooSmallIsAnInputError) {
  CaseSpec c = paper_case();
  c.domain_dp = {15, 200, 10};
  try {
    generate_particles(bubble(1), c);
    FAIL() << "generated in a domain without room for the bubble";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems()[0].where, "/generator/kind");
  }
}

}  // namespace
}  // namespace gridfree
