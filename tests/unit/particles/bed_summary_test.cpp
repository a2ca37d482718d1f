// SPDX-License-Identifier: GPL-3.0-or-later
// The bed summary a job's result carries (particles/bed_summary.h): the
// `ordered` flag separates a lattice from a random packing with the rule of
// BedStructure.RandomEmulsionHasNoPeakOfOrderN (core S/N ≥ 0.05); the
// other numbers are those of a random dense bed.
#include <gtest/gtest.h>

#include "particles/bed_summary.h"
#include "particles/generators.h"
#include "sscp_bed_case.h"

namespace gridfree {
namespace {

using test_support::sscp_bed_case;

GeneratorSpec summary_emulsion(const char* emulsion, std::uint64_t seed) {
  return {"sscp_like",
          {{"kind", "sscp_like"}, {"seed", seed}, {"bed_height_dp", 20}, {"solids_fraction", 0.58},
           {"bubbles", 0}, {"bubble_radius_dp", 3}, {"emulsion", emulsion}},
          "/generator"};
}

nlohmann::json summary_of(const char* emulsion, std::uint64_t seed) {
  const CaseSpec c = sscp_bed_case();
  const auto set = generate_particles(summary_emulsion(emulsion, seed), c);
  const BedStructure s = bed_structure(set.particles, c.domain_cm(), {false, false, false});
  return bed_summary(s, set.particles, c.domain_cm());
}

TEST(BedSummary, LatticeIsOrderedRandomIsNot) {
  const nlohmann::json lattice = summary_of("lattice", 1);
  const nlohmann::json random = summary_of("random", 1);
  EXPECT_TRUE(lattice.at("ordered").get<bool>()) << lattice.dump();
  EXPECT_FALSE(random.at("ordered").get<bool>()) << random.dump();
  // The flag is the core peak against 0.05 (measured: lattice ≈ 0.75 N or
  // more on its layer axis, random a few 1e-3 N).
  EXPECT_GE(lattice.at("largest_structure_factor_core").at("s_over_n").get<double>(), kOrderedPeak);
  EXPECT_LT(random.at("largest_structure_factor_core").at("s_over_n").get<double>(), kOrderedPeak);
}

TEST(BedSummary, RandomBedNumbers) {
  const nlohmann::json s = summary_of("random", 2);
  // 16 × 20 × 8 d at 0.58: N ≈ 0.58 · 2560 / (π/6) ≈ 2836.
  EXPECT_NEAR(s.at("particles").get<double>(), 2836, 10);
  // Bed ε_s over the height of the highest sphere's top: the 0.58 emulsion
  // up to ≈ 20 d (the top surface within a diameter of it), so 0.58 to
  // within 5 %.
  EXPECT_NEAR(s.at("solids_fraction").get<double>(), 0.58, 0.03);
  EXPECT_NEAR(s.at("height_dp").get<double>(), 20, 1);
  // ε_s(y) over the slabs 2 d inside the bed: from 2 d to about 18 d, its
  // range around 0.58 (slabs of one diameter through a random packing
  // scatter by a few hundredths; the walls in x and z lower every slab alike).
  const auto& y = s.at("solids_fraction_y");
  EXPECT_EQ(y.at("from_dp").get<int>(), 2);
  EXPECT_NEAR(y.at("to_dp").get<double>(), 18, 1);
  EXPECT_LE(y.at("min").get<double>(), y.at("max").get<double>());
  EXPECT_GT(y.at("min").get<double>(), 0.45);
  EXPECT_LT(y.at("max").get<double>(), 0.7);
  // g(r): a contact peak near 1 d, g > 1 at √3 d and 2 d (as in
  // BedStructure.RandomEmulsionHasNoPeakOfOrderN).
  EXPECT_GT(s.at("rdf").at("contact_peak").get<double>(), 3.0);
  EXPECT_NEAR(s.at("rdf").at("contact_peak_r_dp").get<double>(), 1.0, 0.05);
  EXPECT_GT(s.at("rdf").at("at_sqrt3_dp").get<double>(), 1.0);
  EXPECT_GT(s.at("local_solids_fraction").at("mean").get<double>(), 0.4);
  EXPECT_GT(s.at("local_solids_fraction").at("std").get<double>(), 0.0);
}

}  // namespace
}  // namespace gridfree
