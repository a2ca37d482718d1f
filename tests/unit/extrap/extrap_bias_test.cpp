// SPDX-License-Identifier: GPL-3.0-or-later
// Bias checks (extrap/bias_checks.h): a declared order the data contradict,
// leave-one-out fits that disagree, and a manufactured series whose windows
// share one bias, which the window comparison alone cannot see. References
// are exact: the series are sums of powers of h with known f0.
#include <cmath>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "extrap/bias_checks.h"
#include "extrap/extrapolation.h"
#include "extrap/self_check.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

using test::geometric_h;
using test::power_law;

bool mentions(const std::vector<std::string>& reasons, const std::string& text) {
  for (const auto& r : reasons)
    if (r.find(text) != std::string::npos) return true;
  return false;
}

// Xing & Stern (2010): FS = 2.45 − 0.85 P for 0 < P ≤ 1, 16.4 P − 14.8 above.
TEST(BiasChecks, XingSternFactorIsThePublishedPiecewiseLine) {
  EXPECT_NEAR(xing_stern_factor(0.5), 2.45 - 0.425, 1e-15);
  EXPECT_NEAR(xing_stern_factor(1.0), 1.6, 1e-15);
  EXPECT_NEAR(xing_stern_factor(1.2), 16.4 * 1.2 - 14.8, 1e-12);
}

// f = 1 + h on 7 grids, h = 0.01 … 0.64 (ratio 2): first-order data. Without
// a declared order the series is converged (p = 1, exact fit); declared
// second order, it is not, and U₁ = FS(1/2) |f0 − f₁| = 2.025 · 0.01.
TEST(BiasChecks, ADeclaredOrderTheDataContradictIsNotConverged) {
  const auto h = geometric_h(7, 0.01, 0.64);
  const auto f = power_law(h, 1.0, 1.0, 1.0);
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kCapped;
  const ExtrapolationResult free = extrapolate(h, f, opts);
  ASSERT_EQ(free.verdict.value, "converged");
  EXPECT_FALSE(free.bias.order_consistent.has_value());

  opts.expected_order = 2.0;
  const ExtrapolationResult r = extrapolate(h, f, opts);
  EXPECT_EQ(r.verdict.value, "pre-asymptotic");
  EXPECT_TRUE(mentions(r.verdict.reasons, "contradicts the declared order 2"));
  ASSERT_TRUE(r.bias.order_consistent.has_value());
  EXPECT_FALSE(*r.bias.order_consistent);
  EXPECT_NEAR(*r.bias.order_ratio, 0.5, 1e-8);
  EXPECT_NEAR(*r.bias.order_factor, 2.025, 1e-7);
  EXPECT_NEAR(*r.f0, 1.0, 1e-10);
  EXPECT_NEAR(*r.grids.front().u, 2.025 * 0.01, 1e-9);
  ASSERT_TRUE(r.verdict.next_h.has_value());
  EXPECT_NEAR(*r.verdict.next_h, 0.005, 1e-12);

  // The default method judges the same way.
  ExtrapolationOptions averaged;
  averaged.expected_order = 2.0;
  EXPECT_NE(extrapolate(h, f, averaged).verdict.value, "converged");
}

// f = 1 + h² declared second order: consistent, still converged; U₁ uses
// FS(1) = 1.6 instead of 1.25.
TEST(BiasChecks, ADeclaredOrderTheDataFollowStaysConverged) {
  const auto h = geometric_h(7, 0.01, 0.64);
  const auto f = power_law(h, 1.0, 1.0, 2.0);
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kCapped;
  opts.expected_order = 2.0;
  const ExtrapolationResult r = extrapolate(h, f, opts);
  EXPECT_EQ(r.verdict.value, "converged");
  EXPECT_TRUE(*r.bias.order_consistent);
  EXPECT_NEAR(*r.grids.front().u, 1.6 * 1e-4, 1e-10);
}

TEST(BiasChecks, ANonPositiveDeclaredOrderIsRefused) {
  ExtrapolationOptions opts;
  opts.expected_order = 0.0;
  EXPECT_THROW(validate_options(opts), InputError);
}

// Exact first-order data with the coarsest value moved: the fit without the
// coarsest grid is exact again, f0 = 1.
TEST(BiasChecks, TheLeaveOneOutFitsAreTheSeriesWithoutEitherEnd) {
  const auto h = geometric_h(7, 0.01, 0.64);
  auto f = power_law(h, 1.0, 1.0, 1.0);
  f.back() += 0.05;
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kCapped;
  const ExtrapolationResult r = extrapolate(h, f, opts);
  ASSERT_TRUE(r.bias.f0_without_coarsest.has_value());
  EXPECT_NEAR(*r.bias.f0_without_coarsest, 1.0, 1e-9);
  ASSERT_TRUE(r.bias.f0_without_finest.has_value());
  // U holds both: U_i ≥ 1.25 |f0_k − f_i| + σ_RE.
  for (double v : {*r.bias.f0_without_coarsest, *r.bias.f0_without_finest})
    for (const auto& g : r.grids) EXPECT_GE(*g.u, 1.25 * std::fabs(v - g.f) + *r.sigma_re - 1e-15);
  opts.leave_one_out = false;
  EXPECT_FALSE(extrapolate(h, f, opts).bias.leave_one_out_agree.has_value());
}

// The rule itself, with a stand-in for the refits: a fit without the finest
// grid 10 U₀ away fails the test, widens U to hold it and demotes converged.
TEST(BiasChecks, LeaveOneOutFitsThatDisagreeAreNotConverged) {
  const auto h = geometric_h(7, 0.01, 0.64);
  const auto f = power_law(h, 1.0, 1.0, 1.0);
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kCapped;
  opts.leave_one_out = false;
  ExtrapolationResult r = extrapolate(h, f, opts);
  ASSERT_EQ(r.verdict.value, "converged");
  const double f0 = *r.f0, u0 = *r.u0;
  const Series s = make_series(h, f);
  const SubSeriesF0 refit = [&](const Series& sub) -> std::optional<double> {
    return sub.h.front() == h.front() ? f0 : f0 + 10 * u0;  // without the finest: far off
  };
  opts.leave_one_out = true;
  const auto failed = apply_bias_checks(s, opts, refit, r);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NE(failed[0].find("f0 without the finest grid"), std::string::npos);
  EXPECT_FALSE(*r.bias.leave_one_out_agree);
  EXPECT_NEAR(*r.grids.front().u, 1.25 * std::fabs(f0 + 10 * u0 - f.front()) + *r.sigma_re, 1e-12);
  EXPECT_NEAR(*r.u0, u0 + 1.25 * 10 * u0, 1e-12);
  demote_for_bias(failed, s.h, r.verdict);
  EXPECT_EQ(r.verdict.value, "pre-asymptotic");
  EXPECT_EQ(r.verdict.reasons.front(), failed.front());
}

// The leave-one-out sentence quotes f0, the refit's f0, their difference and
// U₀ to the digits f0 ± U₀ is printed with after the check widened U₀:
// U₀ = 1.0 + 1.25·2.43 = 4.04 → "4.0", one decimal; 1019.43 → "1019.4",
// 1017.0 → "1017.0", the difference of the printed values 2.4.
TEST(BiasChecks, LeaveOneOutSentenceQuotesTheDigitsOfFZeroPlusMinusU) {
  const auto h = geometric_h(6, 0.5, 1.2);
  std::vector<double> f;
  for (double x : h) f.push_back(1017.0 + x);
  ExtrapolationResult r;
  r.method = "power";
  r.f0 = 1017.0;
  r.u0 = 1.0;
  r.sigma_re = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) r.grids.push_back({h[i], f[i], f[i], 1.0, 1.0 / 1017.0});
  const Series s = make_series(h, f);
  const SubSeriesF0 refit = [&](const Series& sub) -> std::optional<double> {
    return sub.h.front() == h.front() ? 1017.8 : 1019.43;  // without the coarsest: 0.8 < U₀, agrees
  };
  const auto failed = apply_bias_checks(s, ExtrapolationOptions{}, refit, r);
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_NEAR(*r.u0, 1.0 + 1.25 * 2.43, 1e-9);
  EXPECT_NE(failed[0].find("f0 without the finest grid (1019.4) differs from f0 = 1017.0 by 2.4 > U₀ = 1.0 "),
            std::string::npos)
      << failed[0];
}

// f = 1 + 0.1 h + h² on 8 grids, h = 0.1 … 1.71: the h² term dominates the
// grids, so every window and the whole series see p ≈ 2 and share one bias.
// The window comparison covers 10 of 10 while f₁ ± U₁ misses the exact 1;
// declared first order (the h term is the leading one), the check is flagged,
// the series is not converged, and U₁ covers 1.
TEST(BiasChecks, ASharedBiasTheWindowsCannotSeeIsFlaggedByTheOrderTest) {
  const auto h = geometric_h(8, 0.1, 0.1 * std::pow(1.5, 7));
  const auto f = test::mixed_law(h, 1.0, 0.1, 1.0);
  ExtrapolationOptions opts;
  opts.method = ExtrapolationMethod::kCapped;
  const auto fit_with = [](const ExtrapolationOptions& o) {
    return [o](const std::vector<double>& wh, const std::vector<double>& wf) {
      return window_fit(extrapolate(Series{wh, wf}, o));
    };
  };
  const ExtrapolationResult plain = extrapolate(h, f, opts);
  const CoverageCheck blind = coverage_self_check(h, f, fit_with(opts));
  EXPECT_EQ(plain.verdict.value, "converged");
  EXPECT_EQ(blind.covered, blind.judged);
  EXPECT_FALSE(blind.flagged());
  EXPECT_GT(std::fabs(1.0 - f.front()), *plain.grids.front().u);  // the exact answer is missed

  opts.expected_order = 1.0;
  const ExtrapolationResult declared = extrapolate(h, f, opts);
  const CoverageCheck check = coverage_self_check(h, f, fit_with(opts));
  EXPECT_TRUE(check.flagged());
  EXPECT_FALSE(check.below_promise());
  EXPECT_EQ(check.order_consistent, std::optional<bool>(false));
  EXPECT_NE(check.summary().find("contradicts the declared one"), std::string::npos);
  EXPECT_NE(declared.verdict.value, "converged");
  EXPECT_LE(std::fabs(1.0 - f.front()), *declared.grids.front().u);
  Verdict v = plain.verdict;
  demote_if_flagged(check, make_series(h, f).h, v);
  EXPECT_EQ(v.value, "pre-asymptotic");
}

// The default method: U holds f0 of every admissible expansion. On exact
// second-order data the first-order fit f0 + α h is admissible (σ < R_f);
// its f0, computed here in closed form (weighted and unweighted least
// squares, the smaller σ), widens U₁ to 1.25 |f0_first − f₁|.
TEST(ModelAverage, UHoldsTheFirstOrderFitOnSecondOrderData) {
  const auto h = geometric_h(7, 0.01, 0.64);
  const auto f = power_law(h, 1.0, 1.0, 2.0);
  const auto line = [&](bool weighted) {
    const std::size_t n = h.size();
    std::vector<double> w(n, 1.0);
    if (weighted)
      for (std::size_t i = 0; i < n; ++i) w[i] = 1.0 / h[i];
    double sw = 0, sx = 0, sy = 0;
    for (std::size_t i = 0; i < n; ++i) sw += w[i], sx += w[i] * h[i], sy += w[i] * f[i];
    const double mx = sx / sw, my = sy / sw;
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < n; ++i) sxy += w[i] * (h[i] - mx) * (f[i] - my), sxx += w[i] * (h[i] - mx) * (h[i] - mx);
    const double b = sxy / sxx, a = my - b * mx;
    double ss = 0;
    for (std::size_t i = 0; i < n; ++i) ss += w[i] / sw * n * std::pow(f[i] - a - b * h[i], 2);
    return std::pair{a, std::sqrt(ss / (n - 2))};
  };
  const auto [a_u, s_u] = line(false);
  const auto [a_w, s_w] = line(true);
  const double f0_first = s_w <= s_u ? a_w : a_u;
  const ExtrapolationResult r = extrapolate(h, f);  // default: averaged
  ASSERT_TRUE(r.model_spread.has_value());
  bool found = false;
  for (double v : r.model_spread->f0) found = found || std::fabs(v - f0_first) < 1e-9;
  EXPECT_TRUE(found);
  EXPECT_NEAR(*r.f0, 1.0, 1e-10);
  EXPECT_NEAR(*r.grids.front().u, 1.25 * std::fabs(f0_first - f.front()) + *r.sigma_re, 1e-9);
  EXPECT_EQ(r.verdict.value, "converged");
}

// An `unreliable` window of the default method keeps U no smaller than 3 Δφ,
// Δφ = (f_max − f_min)/(n − 1): here four grids flat at the fine end, whose
// capped U₁ (0.0011) is a third of the data's spread; 3 Δφ = 0.003 exactly.
// Other methods are left as they are.
TEST(ModelAverage, AnUnreliableWindowKeepsUAtLeastThreeDataRanges) {
  const std::vector<double> h{1, 2, 4, 8}, f{1.0, 1.0, 1.001, 1.003};
  const double floor = 3 * (1.003 - 1.0) / 3;
  ExtrapolationOptions capped;
  capped.method = ExtrapolationMethod::kCapped;
  const ExtrapolationResult c = extrapolate(h, f, capped);
  ASSERT_EQ(c.verdict.value, "unreliable");
  EXPECT_LT(*c.grids.front().u, floor);  // the floor below is not already there
  const ExtrapolationResult a = extrapolate(h, f);  // default: averaged
  ASSERT_EQ(a.verdict.value, "unreliable");
  for (const auto& g : a.grids) EXPECT_GE(*g.u, floor - 1e-15) << "h = " << g.h;
  EXPECT_NEAR(*a.grids.front().u, floor, 1e-15);
  ASSERT_TRUE(a.u0.has_value());
  EXPECT_GE(*a.u0, floor - 1e-15);
  bool noted = false;
  for (const auto& n : a.notes) noted = noted || n.find("at least 3 times the data range") != std::string::npos;
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace gridfree
