// SPDX-License-Identifier: GPL-3.0-or-later
// Three-grid GCI (Celik et al. 2008) against the paper's worked examples and
// against hand-computed cases, plus its failure modes.
#include <array>
#include <cmath>

#include <gtest/gtest.h>

#include "extrap/gci.h"

namespace gridfree {
namespace {

// Celik et al. (2008), Table 1: 2-D grids, so h ∝ N^(−1/2). The expected
// values are the paper's printed ones; tolerances are half a unit of the
// last printed digit (p to 2 decimals, or 1 for "1.5"; φ_ext to 4 decimals;
// e_a and GCI as percentages with 1 decimal). e_ext21 is checked against its
// definition evaluated with the printed φ_ext (C08 eq. 7b).
struct CelikColumn {
  double n1, n2, n3, phi1, phi2, phi3;
  double p, p_tol, phi_ext, e_a, gci;
  const char* convergence;
};

class CelikTable1 : public ::testing::TestWithParam<CelikColumn> {};

TEST_P(CelikTable1, ReproducesPrintedValues) {
  const CelikColumn c = GetParam();
  const GciTriplet t = gci_triplet({1 / std::sqrt(c.n1), 1 / std::sqrt(c.n2), 1 / std::sqrt(c.n3)},
                                   {c.phi1, c.phi2, c.phi3});
  ASSERT_EQ(t.status, "ok");
  EXPECT_NEAR(*t.p, c.p, c.p_tol);
  EXPECT_NEAR(*t.f_ext, c.phi_ext, 0.5e-4);
  EXPECT_NEAR(100 * *t.e_a21, c.e_a, 0.05);
  EXPECT_NEAR(*t.e_ext21, std::fabs((c.phi_ext - c.phi1) / c.phi_ext), 1e-5);
  EXPECT_NEAR(100 * *t.gci_fine, c.gci, 0.05);
  EXPECT_EQ(*t.convergence, c.convergence);
  // The absolute GCI is the relative one times |φ1|.
  EXPECT_NEAR(*t.gci_fine_abs, *t.gci_fine * std::fabs(c.phi1), 1e-15);
}

INSTANTIATE_TEST_SUITE_P(
    Columns, CelikTable1,
    ::testing::Values(
        // φ = dimensionless reattachment length, N = 18000, 8000, 4500.
        CelikColumn{18000, 8000, 4500, 6.063, 5.972, 5.863, 1.53, 0.005, 6.1685, 1.5, 2.2, "monotone"},
        // axial velocity, N = 18000, 4500, 980 (r21 = 2, r32 = 2.143).
        CelikColumn{18000, 4500, 980, 10.7880, 10.7250, 10.6050, 0.75, 0.005, 10.8801, 0.6, 1.1, "monotone"},
        // axial velocity (oscillatory), N = 18000, 4500, 980.
        CelikColumn{18000, 4500, 980, 6.0042, 5.9624, 6.0909, 1.5, 0.05, 6.0269, 0.7, 0.5, "oscillatory"}));

TEST(ExtrapGci, ConstantRatioNeedsNoIteration) {
  // r21 = r32 = 2 makes q ≡ 0: p = ln(ε32/ε21)/ln 2 exactly. f = 1 + h²:
  // ε21 = 3, ε32 = 12, p = 2, φ_ext = (4·2 − 5)/3 = 1, GCI = 1.25·(3/2)/3.
  const GciTriplet t = gci_triplet({1, 2, 4}, {2, 5, 17});
  EXPECT_NEAR(*t.p, 2.0, 1e-14);
  EXPECT_NEAR(*t.f_ext, 1.0, 1e-14);
  EXPECT_NEAR(*t.e_a21, 1.5, 1e-15);
  EXPECT_NEAR(*t.e_ext21, 1.0, 1e-14);
  EXPECT_NEAR(*t.gci_fine, 1.25 * 1.5 / 3, 1e-14);
  EXPECT_EQ(*t.convergence, "monotone");
  EXPECT_LE(t.iterations, 2);
}

TEST(ExtrapGci, VariableRatioSolvesTheImplicitEquation) {
  // Exact f = 3 + 0.5 h^1.7 on r21 = 1.3, r32 = 1.9: the iteration must return
  // p = 1.7 and φ_ext = 3 (Richardson extrapolation is exact for one term).
  const double h1 = 0.4, h2 = 0.52, h3 = 0.988;
  auto f = [](double h) { return 3 + 0.5 * std::pow(h, 1.7); };
  const GciTriplet t = gci_triplet({h1, h2, h3}, {f(h1), f(h2), f(h3)});
  ASSERT_EQ(t.status, "ok");
  EXPECT_NEAR(*t.p, 1.7, 1e-10);
  EXPECT_NEAR(*t.f_ext, 3.0, 1e-10);
}

TEST(ExtrapGci, ConvergenceLabels) {
  EXPECT_EQ(*gci_triplet({1, 2, 4}, {1.0, 1.5, 1.2}).convergence, "oscillatory");  // R = 0.5/−0.3
  EXPECT_EQ(*gci_triplet({1, 2, 4}, {1.0, 2.0, 2.5}).convergence, "divergent");    // R = 1/0.5 = 2
  EXPECT_EQ(*gci_triplet({1, 2, 4}, {1.0, 1.2, 2.0}).convergence, "monotone");     // R = 0.25
}

// Exact f0 + k h^p on unequal ratios, as a series has after a failed grid
// is dropped (r21 = 1.43, r32 = 1.19). The rule R = ε21/ε32 < 1 called this
// divergent: here R = (r21^p − 1)/(r21^p (r32^p − 1)) = 1.36 at p = 1.6.
GciTriplet exact_triplet(double f0, double k, double p, double h1, double r21, double r32) {
  const std::array<double, 3> h{h1, h1 * r21, h1 * r21 * r32};
  return gci_triplet(h, {f0 + k * std::pow(h[0], p), f0 + k * std::pow(h[1], p), f0 + k * std::pow(h[2], p)});
}

TEST(ExtrapGci, UnequalRatiosOfExactDataAreMonotone) {
  for (const double p : {0.6, 1.0, 1.6, 2.0, 3.0}) {
    for (const double k : {40.0, -40.0}) {  // from above and from below
      const GciTriplet t = exact_triplet(1015.855, k, p, 0.5, 1.43, 1.19);
      ASSERT_TRUE(t.convergence) << p;
      EXPECT_EQ(*t.convergence, "monotone") << "p " << p << " k " << k << " R " << *t.ratio;
      ASSERT_EQ(t.status, "ok");
      // One term: the implicit equation and Richardson extrapolation are exact
      // up to the iteration's 1e-13 and rounding in the differences.
      EXPECT_NEAR(*t.p, p, 1e-8 * p) << p;
      EXPECT_NEAR(*t.f_ext, 1015.855, 1e-8) << p;
    }
  }
  // The case of the report: p = 1.6 has R > 1.
  EXPECT_GT(*exact_triplet(1015.855, 40, 1.6, 0.5, 1.43, 1.19).ratio, 1.3);
  // And the reverse order of ratios (r21 < r32), where R < 1 held already.
  EXPECT_EQ(*exact_triplet(2.0, 1.0, 1.6, 0.1, 1.19, 1.43).convergence, "monotone");
}

TEST(ExtrapGci, UnequalRatiosOfDivergingDataAreDivergent) {
  // f = f0 + k h^p with p < 0: the differences grow as h falls. With these
  // ratios ε32/ε21 = g(p) < g(0+) = ln r32/ln r21 = 0.487 for every p < 0.
  for (const double p : {-0.3, -1.0, -2.0}) {
    const GciTriplet t = exact_triplet(1.0, 1.0, p, 0.5, 1.43, 1.19);
    ASSERT_TRUE(t.convergence);
    EXPECT_EQ(*t.convergence, "divergent") << p;
  }
  // Equal differences on unequal ratios: ε32/ε21 = 1 < ln 10/ln 2 = 3.32.
  EXPECT_EQ(*gci_triplet({1, 2, 20}, {1.0, 2.0, 3.0}).convergence, "divergent");
  // Equal differences with r21 = 1.43 > r32 = 1.19: 1 > 0.487, so a p > 0
  // fits (the coarser step is smaller): monotone, not divergent.
  EXPECT_EQ(*gci_triplet({0.5, 0.715, 0.85085}, {1.0, 2.0, 3.0}).convergence, "monotone");
}

TEST(ExtrapGci, UnequalRatiosOfAlternatingDataAreOscillatory) {
  // f0 + k (−1)^i h_i^p: the sign of ε32/ε21 is negative whatever the ratios.
  const std::array<double, 3> h{0.5, 0.5 * 1.43, 0.5 * 1.43 * 1.19};
  const GciTriplet t = gci_triplet(h, {1 + std::pow(h[0], 1.5), 1 - std::pow(h[1], 1.5), 1 + std::pow(h[2], 1.5)});
  ASSERT_TRUE(t.convergence);
  EXPECT_EQ(*t.convergence, "oscillatory");
}

TEST(ExtrapGci, EqualRatiosKeepTheRatioRule) {
  // r21 = r32: ln r32/ln r21 = 1, so monotone ⇔ ε32/ε21 > 1 ⇔ 0 < R < 1.
  for (const double R : {0.1, 0.5, 0.99, 1.0, 1.01, 2.0}) {
    const GciTriplet t = gci_triplet({1, 2, 4}, {1.0, 1.0 + R, 1.0 + R + 1.0});
    EXPECT_EQ(*t.convergence, R < 1 ? "monotone" : "divergent") << R;
  }
}

TEST(ExtrapGci, ZeroDifferenceHasNoNumbers) {
  const GciTriplet t = gci_triplet({1, 2, 4}, {1.0, 1.0, 2.0});
  EXPECT_EQ(t.status, "zero_difference");
  EXPECT_FALSE(t.p.has_value());
  EXPECT_FALSE(t.f_ext.has_value());
  EXPECT_FALSE(t.gci_fine.has_value());
  EXPECT_FALSE(gci_triplet({1, 2, 4}, {1.0, 2.0, 2.0}).convergence.has_value());
}

TEST(ExtrapGci, IterationFailureIsDetected) {
  // ε32 = ε21 with r21 ≠ r32: the first iterate is p = 0, where
  // q = ln(0/0) is undefined.
  const GciTriplet a = gci_triplet({1, 2, 20}, {1.0, 2.0, 3.0});
  EXPECT_EQ(a.status, "no_convergence_of_order_iteration");
  EXPECT_FALSE(a.p.has_value());
  // r32 ≫ r21: the fixed-point map has slope ≈ 1 − ln r32/ln r21 ≈ −6 near the
  // root, so the iteration cannot settle; it must stop and say so.
  const GciTriplet b = gci_triplet({1, 1.1, 2.2}, {1.0, 1.05, 1.9});
  EXPECT_EQ(b.status, "no_convergence_of_order_iteration");
  EXPECT_FALSE(b.f_ext.has_value());
  EXPECT_LE(b.iterations, kGciMaxIterations + 1);
}

TEST(ExtrapGci, ZeroFineValueKeepsAbsoluteNumbers) {
  const GciTriplet t = gci_triplet({1, 2, 4}, {0.0, 3.0, 15.0});
  EXPECT_EQ(t.status, "zero_fine_value");
  EXPECT_NEAR(*t.p, 2.0, 1e-14);
  EXPECT_FALSE(t.gci_fine.has_value());
  EXPECT_NEAR(*t.gci_fine_abs, 1.25 * 3 / 3, 1e-14);
}

TEST(ExtrapGci, TripletsAreConsecutiveFinestFirst) {
  const Series s = make_series({4, 1, 3, 2, 5}, {4, 1, 3, 2, 5.5});
  const auto ts = gci_triplets(s);
  ASSERT_EQ(ts.size(), 3u);
  EXPECT_EQ(ts[0].h[0], 1);
  EXPECT_EQ(ts[1].h[0], 2);
  EXPECT_EQ(ts[2].h[2], 5);
}

}  // namespace
}  // namespace gridfree
