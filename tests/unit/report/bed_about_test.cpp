// SPDX-License-Identifier: GPL-3.0-or-later
// "About this case: bed structure" (report/bed_about.h): one line per case
// and one per ensemble with ranges over its instances, the ordered flag at a
// core peak of 0.05 N, and no section when no result carries a bed.
#include <gtest/gtest.h>

#include "report/bed_about.h"

namespace gridfree {
namespace {

nlohmann::json bed_of(double core_peak, double contact, double eps) {
  return {{"particles", 4649},
          {"height_dp", 50.0},
          {"solids_fraction", eps},
          {"largest_structure_factor", {{"axis", "y"}, {"period_dp", 1.0}, {"s_over_n", 0.012}}},
          {"largest_structure_factor_core", {{"axis", "x"}, {"period_dp", 0.75}, {"s_over_n", core_peak}}},
          {"ordered", core_peak >= 0.05},
          {"rdf", {{"contact_peak", contact}, {"contact_peak_r_dp", 1.01}, {"at_sqrt3_dp", 1.13}, {"at_2_dp", 1.31}}},
          {"solids_fraction_y", {{"min", 0.28}, {"max", 0.33}, {"from_dp", 2}, {"to_dp", 48}}},
          {"local_solids_fraction", {{"cube_dp", 3}, {"mean", 0.3}, {"std", 0.04}}}};
}

const std::string& paragraph_starting(const AboutSection& s, const std::string& head) {
  for (const auto& p : s.paragraphs)
    if (p.rfind(head, 0) == 0) return p;
  static const std::string none;
  ADD_FAILURE() << "no paragraph starting '" << head << "'";
  return none;
}

TEST(BedAbout, OneLinePerCaseWithItsNumbers) {
  const auto s = bed_about_section({"PC1", "PC1", "PC2"}, {{"PC1", bed_of(0.004, 3.21, 0.185)}}, {});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->title, "About this case: bed structure");
  // The reading rule first.
  EXPECT_NE(s->paragraphs.at(0).find("a random packing gives S/N of order 1/N, a crystal of order 1"), std::string::npos);
  EXPECT_EQ(paragraph_starting(*s, "PC1: "),
            "PC1: N 4649, ε_s 0.185 (bed height 50.0 d); largest S/N 0.012 (y, period 1.00 d), in the core 0.004 "
            "(x, period 0.75 d): random (core peak < 0.05 N); g(r) contact peak 3.21 at 1.01 d, g(√3 d) 1.13, "
            "g(2 d) 1.31; ε_s(y) 0.280 to 0.330 over y 2 to 48 d; local ε_s 0.300 ± 0.040.");
  EXPECT_EQ(s->paragraphs.size(), 3u);  // rule, PC1 (once), the case without a bed
  EXPECT_NE(s->paragraphs.back().find("PC2"), std::string::npos);
}

TEST(BedAbout, EnsembleIsOneLineOfRanges) {
  const std::map<std::string, nlohmann::json> beds = {{"t1", bed_of(0.002, 3.1, 0.58)},
                                                      {"t2", bed_of(0.61, 7.2, 0.58)},
                                                      {"t3", bed_of(0.003, 3.3, 0.58)}};
  const auto s = bed_about_section({"t1", "t2", "t3", "lone"}, beds, {{"snap", {"t1", "t2", "t3"}}});
  ASSERT_TRUE(s);
  const std::string& line = paragraph_starting(*s, "ensemble snap (3 instances): ");
  EXPECT_NE(line.find("ε_s 0.580 (bed height"), std::string::npos) << line;     // equal: one number
  EXPECT_NE(line.find("in the core 0.002 – 0.61 (largest: x, period 0.75 d)"), std::string::npos) << line;
  EXPECT_NE(line.find("ORDERED in 1 of 3 instances"), std::string::npos) << line;
  EXPECT_NE(line.find("g(r) contact peak 3.10 – 7.20"), std::string::npos) << line;
  for (const auto& p : s->paragraphs) EXPECT_NE(p.rfind("t2:", 0), 0u) << "an instance got its own line";
}

TEST(BedAbout, OrderedSingleCaseAndNoBedsNoSection) {
  const auto s = bed_about_section({"lat"}, {{"lat", bed_of(0.75, 7.0, 0.58)}}, {});
  ASSERT_TRUE(s);
  EXPECT_NE(paragraph_starting(*s, "lat: ").find("ORDERED (core peak ≥ 0.05 N)"), std::string::npos);
  // Without the worker's flag, the same rule here: exactly at the
  // threshold is ordered (≥), as particles/bed_summary.h.
  nlohmann::json edge = bed_of(0.05, 3, 0.5);
  edge.erase("ordered");
  EXPECT_NE(paragraph_starting(*bed_about_section({"e"}, {{"e", edge}}, {}), "e: ").find("ORDERED"), std::string::npos);
  // With it, the worker's flag decides.
  nlohmann::json flagged = bed_of(0.01, 3, 0.5);
  flagged["ordered"] = true;
  EXPECT_NE(paragraph_starting(*bed_about_section({"f"}, {{"f", flagged}}, {}), "f: ").find("ORDERED"), std::string::npos);
  EXPECT_FALSE(bed_about_section({"PC1"}, {}, {}));
}

}  // namespace
}  // namespace gridfree
