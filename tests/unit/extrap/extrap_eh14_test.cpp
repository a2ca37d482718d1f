// SPDX-License-Identifier: GPL-3.0-or-later
// The Eça & Hoekstra (2014) option: which fit and which rule is applied for
// each range of the observed order, and U recomputed independently from the
// reported fit (EH14 eqs. 19-21).
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/eh14.h"
#include "extrap/extrapolation.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

ExtrapolationResult eh14(const std::vector<double>& h, const std::vector<double>& f) {
  return extrapolate(h, f, test::formula_of(ExtrapolationMethod::kEh14));
}

// U_i from EH14 eqs. 19-21 with ε_i = |f̂_i − f0| and the reported σ, Fs.
void expect_eh14_uncertainties(const ExtrapolationResult& r, double fs_expected) {
  double fmin = r.grids[0].f, fmax = fmin;
  for (const auto& g : r.grids) fmin = std::min(fmin, g.f), fmax = std::max(fmax, g.f);
  const double range = (fmax - fmin) / (r.grids.size() - 1);
  const double sigma = *r.sigma_re;
  for (const auto& g : r.grids) {
    const double eps = std::fabs(*g.fhat - *r.f0), dev = std::fabs(g.f - *g.fhat);
    const double u = sigma < range ? fs_expected * eps + sigma + dev
                                   : 3 * sigma / range * (eps + sigma + dev);
    EXPECT_NEAR(*g.u, u, 1e-9 * std::max(1.0, u));
  }
}

TEST(ExtrapEh14, ExpectedOrderUsesThePowerLawWithFs125) {
  const auto h = test::default_h();
  const auto r = eh14(h, test::power_law(h, 4.0, 0.3, 1.2));
  EXPECT_EQ(r.eh14->order, "expected_order");
  EXPECT_EQ(r.eh14->scatter, "sigma_below_data_range");
  // Exact data: both weightings have σ ≈ 0; either may win the tie.
  EXPECT_TRUE(*r.method == "eh14_power_weighted" || *r.method == "eh14_power_unweighted") << *r.method;
  EXPECT_NEAR(*r.f0, 4.0, 1e-10);
  EXPECT_NEAR(*r.p, 1.2, 1e-10);
  EXPECT_EQ(*r.fs, 1.25);
  expect_eh14_uncertainties(r, 1.25);
  // Reduces to U = 1.25 |f0 − f_i| for exact single-term data (the GCI).
  for (const auto& g : r.grids) EXPECT_NEAR(*g.u, 1.25 * std::fabs(4.0 - g.f), 1e-9);
}

TEST(ExtrapEh14, HighOrderUsesFixedFirstOrSecondOrderWithFs3) {
  const auto h = test::default_h();
  const auto r = eh14(h, test::power_law(h, 4.0, 0.3, 3.0));
  EXPECT_EQ(r.eh14->order, "high_order");
  EXPECT_NEAR(*r.eh14->p, 3.0, 1e-10);
  const std::string m = *r.method;
  EXPECT_TRUE(m.rfind("eh14_first_", 0) == 0 || m.rfind("eh14_second_", 0) == 0) << m;
  if (r.eh14->scatter == "sigma_below_data_range") {
    EXPECT_EQ(*r.fs, 3.0);
  }
  expect_eh14_uncertainties(r, 3.0);
}

TEST(ExtrapEh14, LowOrderConsidersTheMixedFitToo) {
  // p = 0.3 data: fixed-order fits with Fs = 3. Exact mixed data: the best
  // single power has p < 0.5, and among δ_1, δ_2, δ_12 the exact δ_12 has the
  // smallest σ (≈ 0), so it must be selected.
  const auto h = test::default_h();
  const auto r = eh14(h, test::power_law(h, 4.0, 0.3, 0.3));
  EXPECT_EQ(r.eh14->order, "low_order");
  const auto rm = eh14(h, test::mixed_law(h, 4.0, 1.0, -0.25));
  EXPECT_EQ(rm.eh14->order, "low_order");  // best single power is p ≈ −0.08
  EXPECT_TRUE(rm.method->rfind("eh14_mixed_", 0) == 0) << *rm.method;
  EXPECT_NEAR(*rm.f0, 4.0, 1e-9);
  EXPECT_EQ(*rm.fs, 3.0);
  expect_eh14_uncertainties(r, 3.0);
}

TEST(ExtrapEh14, ScatteredDataUseEquation21) {
  const auto h = test::default_h();
  std::vector<double> f;
  for (std::size_t i = 0; i < h.size(); ++i) f.push_back(i % 2 ? 1.0 : -1.0);
  const auto r = eh14(h, f);
  EXPECT_EQ(r.eh14->scatter, "sigma_at_least_data_range");
  EXPECT_NEAR(*r.fs, 3 * *r.sigma_re / *r.data_range, 1e-12);
  expect_eh14_uncertainties(r, 3.0);
}

TEST(ExtrapEh14, OscillatorySeriesIsSelfConsistent) {
  const auto h = test::oscillatory_h();
  const auto r = eh14(h, test::oscillatory_f(h));
  ASSERT_TRUE(r.eh14.has_value());
  EXPECT_TRUE(r.first.has_value());
  EXPECT_TRUE(r.second.has_value());
  const bool fs125 = r.eh14->order == "expected_order" && r.eh14->scatter == "sigma_below_data_range" &&
                     *r.eh14->p < 2.1;
  expect_eh14_uncertainties(r, fs125 ? 1.25 : 3.0);
}

TEST(ExtrapEh14, EquationsTwentyAndTwentyOne) {
  // σ < Δφ: Fs ε + σ + dev;  σ ≥ Δφ: 3σ/Δφ (ε + σ + dev).
  EXPECT_DOUBLE_EQ(eh14_uncertainty(2.0, 0.1, 0.05, 1.0, 1.25), 1.25 * 2.0 + 0.1 + 0.05);
  EXPECT_DOUBLE_EQ(eh14_uncertainty(2.0, 1.5, 0.05, 1.0, 1.25), 3 * 1.5 / 1.0 * (2.0 + 1.5 + 0.05));
}

}  // namespace
}  // namespace gridfree
