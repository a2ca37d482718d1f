// SPDX-License-Identifier: GPL-3.0-or-later
// Weighted least squares, the power-law fit and the fixed-order fits against
// data built from known coefficients (exact up to rounding of the data).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/least_squares.h"
#include "extrap/mixed_fit.h"
#include "extrap/power_fit.h"
#include "extrap/series.h"
#include "expect_relative.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

// Relative agreement used for recovered coefficients of exact data: the data
// carry rounding errors of ~1e-16 relative, amplified by the conditioning of
// the fits (~1e3 for these grids), leaving far below 1e-10.
constexpr double kExact = 1e-10;

using test_support::expect_rel;

TEST(ExtrapLeastSquares, StraightLineMatchesClosedForm) {
  // Weighted line fit y = a + b x; closed form with weighted means
  // b = Σw(x−x̄)(y−ȳ)/Σw(x−x̄)², a = ȳ − b x̄, computed here independently.
  const std::vector<double> x{0, 1, 2, 3}, y{1.0, 2.9, 5.2, 6.8}, w{0.1, 0.2, 0.3, 0.4};
  double xm = 0, ym = 0;
  for (int i = 0; i < 4; ++i) xm += w[i] * x[i], ym += w[i] * y[i];
  double sxy = 0, sxx = 0;
  for (int i = 0; i < 4; ++i) sxy += w[i] * (x[i] - xm) * (y[i] - ym), sxx += w[i] * (x[i] - xm) * (x[i] - xm);
  const double b = sxy / sxx, a = ym - b * xm;

  Eigen::MatrixXd A(4, 2);
  Eigen::VectorXd yv(4), wv(4);
  for (int i = 0; i < 4; ++i) A(i, 0) = 1, A(i, 1) = x[i], yv(i) = y[i], wv(i) = w[i];
  const LinearFit fit = weighted_least_squares(A, yv, wv);
  EXPECT_NEAR(fit.x(0), a, 1e-13);
  EXPECT_NEAR(fit.x(1), b, 1e-13);
  double S = 0;
  for (int i = 0; i < 4; ++i) S += w[i] * std::pow(y[i] - a - b * x[i], 2);
  EXPECT_NEAR(fit.sum_of_squares, S, 1e-14);
  // σ with k = 2: sqrt(n S/(n − 2)).
  EXPECT_NEAR(fit_standard_deviation(fit.residuals, wv, 2), std::sqrt(4 * S / 2), 1e-13);
  EXPECT_TRUE(std::isnan(fit_standard_deviation(fit.residuals.head(2), wv.head(2), 2)));
}

class ExactPowerLaw : public ::testing::TestWithParam<double> {};

TEST_P(ExactPowerLaw, RecoversF0CAndP) {
  const double p = GetParam();
  const auto h = test::default_h();
  const Series s = make_series(h, test::power_law(h, 1158.8, 0.37, p));
  const auto w = fit_weights(s.h, Weighting::kInverseH);
  const PowerLawFit fit = fit_power_law(s, w);
  EXPECT_TRUE(fit.p_found);
  expect_rel(fit.p, p, kExact);
  expect_rel(fit.f0, 1158.8, kExact);
  expect_rel(fit.c, 0.37, kExact);
  EXPECT_LT(fit.sigma, 1e-9);
  for (std::size_t i = 0; i < s.size(); ++i) expect_rel(fit.fhat[i], s.f[i], 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Orders, ExactPowerLaw, ::testing::Values(0.7, 1.0, 1.9, 3.0, -0.5, 0.5, 2.1, 6.0));

TEST(ExtrapPowerFit, GlobalMinimumBeatsADenseIndependentScan) {
  // Oscillatory data has several local minima of S(p): the reported p must
  // be no worse than any of 20000 independently chosen trial orders.
  const auto h = test::oscillatory_h();
  const Series s = make_series(h, test::oscillatory_f(h));
  const auto w = fit_weights(s.h, Weighting::kInverseH);
  const PowerLawFit fit = fit_power_law(s, w);
  const double S_fit = power_law_profile(s, w, fit.p);
  EXPECT_NEAR(fit.sum_of_squares, S_fit, 1e-12 * S_fit);
  for (int k = 0; k < 20000; ++k) {
    const double p = -10.0 + 20.0 * (k + 0.5) / 20000;
    if (std::fabs(p) < 0.01) continue;
    EXPECT_LE(S_fit, power_law_profile(s, w, p) * (1 + 1e-12)) << "p = " << p;
  }
}

TEST(ExtrapPowerFit, ScanProfileIsTheQrProfile) {
  // The scan's closed form against the QR at every order of the search
  // range, on scattered data (S well above rounding: 1e-10 relative) and on
  // an exact power law, where S at the true order is rounding only: there
  // the two may differ by the rounding of the data, S of ~1e-24 of the
  // data's squared range, nowhere near the minimum's neighbours.
  const auto h = test::oscillatory_h();
  const Series osc = make_series(h, test::oscillatory_f(h));
  const Series exact = make_series(h, test::power_law(h, 1158.8, 0.37, 1.6));
  for (const Weighting weighting : {Weighting::kInverseH, Weighting::kUniform}) {
    const auto w = fit_weights(h, weighting);
    std::vector<double> orders{1.6, 1.6 * (1 + 1e-6), 1.6 * (1 - 1e-4)};  // at and beside the exact order
    for (int k = 0; k <= 400; ++k) orders.push_back((k % 2 ? -1 : 1) * 0.01 * std::pow(1000.0, (k / 2) / 200.0));
    for (const double p : orders) {
      expect_rel(power_law_scan_profile(osc, w, p), power_law_profile(osc, w, p), 1e-10);
      const double range2 = std::pow(exact.f.back() - exact.f.front(), 2);
      EXPECT_NEAR(power_law_scan_profile(exact, w, p), power_law_profile(exact, w, p),
                  1e-10 * power_law_profile(exact, w, p) + 1e-24 * range2)
          << "p = " << p;
    }
  }
}

TEST(ExtrapPowerFit, MinimumOnTheBoundaryIsNotFound) {
  // f = 1 + ln h is the p -> 0 limit of (h^p − 1)/p: S keeps falling towards
  // |p| = 0.01, the edge of the search range.
  const auto h = test::default_h();
  std::vector<double> f;
  for (double hi : h) f.push_back(1 + std::log(hi));
  const Series s = make_series(h, f);
  const PowerLawFit fit = fit_power_law(s, fit_weights(s.h, Weighting::kInverseH));
  EXPECT_FALSE(fit.p_found);
  EXPECT_DOUBLE_EQ(std::fabs(fit.p), 0.01);

  // An order above the range: the minimum sits at p = 10.
  const Series s12 = make_series(h, test::power_law(h, 2.0, 1e-6, 12.0));
  const PowerLawFit fit12 = fit_power_law(s12, fit_weights(s12.h, Weighting::kInverseH));
  EXPECT_FALSE(fit12.p_found);
  EXPECT_DOUBLE_EQ(fit12.p, 10.0);
}

TEST(ExtrapPowerFit, ScaleOfHChangesOnlyC) {
  // h -> 1000 h: same p and f0, c -> c·1000^(−p).
  const auto h = test::oscillatory_h();
  const auto f = test::oscillatory_f(h);
  std::vector<double> hk;
  for (double hi : h) hk.push_back(1000 * hi);
  const Series s = make_series(h, f), sk = make_series(hk, f);
  const PowerLawFit a = fit_power_law(s, fit_weights(s.h, Weighting::kInverseH));
  const PowerLawFit b = fit_power_law(sk, fit_weights(sk.h, Weighting::kInverseH));
  expect_rel(b.p, a.p, 1e-9);
  expect_rel(b.f0, a.f0, 1e-12);
  expect_rel(b.c, a.c * std::pow(1000.0, -a.p), 1e-8);
  expect_rel(b.sigma, a.sigma, 1e-8);
}

TEST(ExtrapMixedFit, RecoversExactMixedData) {
  const auto h = test::default_h();
  const Series s = make_series(h, test::mixed_law(h, 1158.8, -0.21, 0.043));
  const FixedOrderFit fit = fit_mixed(s, fit_weights(s.h, Weighting::kInverseH));
  expect_rel(fit.f0, 1158.8, kExact);
  expect_rel(fit.coefficients[0], -0.21, kExact);
  expect_rel(fit.coefficients[1], 0.043, kExact);
  EXPECT_LT(fit.sigma, 1e-9);
}

TEST(ExtrapMixedFit, FirstAndSecondOrderFits) {
  const auto h = test::default_h();
  const Series s1 = make_series(h, test::mixed_law(h, 2.5, 0.8, 0.0));
  const FixedOrderFit f1 = fit_fixed_orders(s1, fit_weights(s1.h, Weighting::kUniform), {1.0});
  expect_rel(f1.f0, 2.5, kExact);
  expect_rel(f1.coefficients[0], 0.8, kExact);
  const Series s2 = make_series(h, test::mixed_law(h, 2.5, 0.0, -0.3));
  const FixedOrderFit f2 = fit_fixed_orders(s2, fit_weights(s2.h, Weighting::kInverseH), {2.0});
  expect_rel(f2.f0, 2.5, kExact);
  expect_rel(f2.coefficients[0], -0.3, kExact);
}

TEST(ExtrapMixedFit, SigmaMatchesIndependentResidualSum) {
  // Noisy data: σ = sqrt(Σ n w r²/(n − 3)) recomputed from the fitted values.
  const auto h = test::oscillatory_h();
  const Series s = make_series(h, test::oscillatory_f(h));
  const auto w = fit_weights(s.h, Weighting::kInverseH);
  const FixedOrderFit fit = fit_mixed(s, w);
  double sum = 0;
  const double n = static_cast<double>(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) sum += n * w[i] * std::pow(s.f[i] - fit.fhat[i], 2);
  expect_rel(fit.sigma, std::sqrt(sum / (n - 3)), 1e-12);
  // And the fit is a least-squares minimum: nudging any coefficient raises S.
  auto S_of = [&](double f0, double c1, double c2) {
    double S = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      S += w[i] * std::pow(s.f[i] - f0 - c1 * s.h[i] - c2 * s.h[i] * s.h[i], 2);
    return S;
  };
  const double S0 = S_of(fit.f0, fit.coefficients[0], fit.coefficients[1]);
  for (double d : {-1e-4, 1e-4}) {
    EXPECT_GT(S_of(fit.f0 + d, fit.coefficients[0], fit.coefficients[1]), S0);
    EXPECT_GT(S_of(fit.f0, fit.coefficients[0] + d, fit.coefficients[1]), S0);
    EXPECT_GT(S_of(fit.f0, fit.coefficients[0], fit.coefficients[1] + d), S0);
  }
}

}  // namespace
}  // namespace gridfree
