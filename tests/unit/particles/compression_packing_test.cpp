// SPDX-License-Identifier: GPL-3.0-or-later
// The compression emulsion ("emulsion": "compression", particles/
// compression_packing.h) on the generator tests' bed at ε_s = 0.59 (0.45 s;
// 0.60 takes about 45 s on this narrow bed with its bubble): no overlap, no
// structure-factor peak of order N, the same bed for the same seed; above
// its limit 0.60 it is refused (docs/PARTICLES.md).
#include <gtest/gtest.h>

#include "particle_checks.h"
#include "particles/bed_structure.h"
#include "particles/generators.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

using test_support::sscp_bed_case;

GeneratorSpec compression_spec(double fraction, const char* emulsion, std::uint64_t seed = 4) {
  nlohmann::json p = {{"kind", "sscp_like"}, {"seed", seed},          {"bed_height_dp", 20},
                      {"solids_fraction", fraction}, {"bubbles", 1}, {"bubble_radius_dp", 3}};
  if (emulsion != nullptr) p["emulsion"] = emulsion;
  return {"sscp_like", p, "/generator"};
}

TEST(CompressionPacking, NoOverlapNoOrderSameBed) {
  const CaseSpec c = sscp_bed_case();
  const auto set = generate_particles(compression_spec(0.59, "compression"), c);
  EXPECT_EQ(test::count_overlaps(set.particles, c.domain_cm(), {false, false, false}), 0u);
  const BedStructure s = bed_structure(set.particles, c.domain_cm(), {false, false, false});
  // The threshold of BedStructure.RandomEmulsionHasNoPeakOfOrderN: a
  // random core gives S/N of order 1/N_core ≈ 0.002, a crystal 0.5–1.
  EXPECT_LT(s.largest_core_peak.s_over_n, 0.05);
  EXPECT_GT(s.rdf.contact_peak, 3.0);
  EXPECT_GT(s.rdf.dip_between, 0.8);  // no empty shell between √3 d and 2 d

  const auto again = generate_particles(compression_spec(0.59, "compression"), c);
  ASSERT_EQ(again.particles.size(), set.particles.size());
  for (std::size_t i = 0; i < set.particles.size(); ++i) {
    ASSERT_EQ(again.particles[i].x, set.particles[i].x) << i;
    ASSERT_EQ(again.particles[i].y, set.particles[i].y) << i;
    ASSERT_EQ(again.particles[i].z, set.particles[i].z) << i;
  }
}

std::string compression_problem(const GeneratorSpec& spec) {
  try {
    generate_particles(spec, sscp_bed_case());
  } catch (const InputError& e) {
    return e.problems()[0].where + ": " + e.problems()[0].reason;
  }
  return "accepted";
}

TEST(CompressionPacking, AboveSixtyPercentRefused) {
  EXPECT_EQ(compression_problem(compression_spec(0.605, "compression")).rfind("/generator/solids_fraction: 0.605 is above 0.6", 0),
            0u);
}

}  // namespace
}  // namespace gridfree
