// SPDX-License-Identifier: GPL-3.0-or-later
// Verdict rules (docs/EXTRAPOLATION.md "Verdicts"): each rule isolated on a
// hand-built extrapolation result through the pure judge(), then whole
// series through extrapolate() — exact power laws whose verdict follows from
// the rules by arithmetic given in each test's comment.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "extrap/extrapolation.h"
#include "extrap/verdict.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

bool any_reason_contains(const Verdict& v, const std::string& text) {
  for (const auto& r : v.reasons)
    if (r.find(text) != std::string::npos) return true;
  return false;
}

// A fitted power-law result for judge(): f on h (ascending), f0, p, σ/R_f and
// the finest RDE set directly; R_f from f as the library computes it.
ExtrapolationResult fitted(const std::vector<double>& h, const std::vector<double>& f, double f0, double p,
                           double sigma_over_range, double rde_finest) {
  ExtrapolationResult r;
  r.method = "power";
  r.f0 = f0;
  r.p = p;
  r.sigma_over_range = sigma_over_range;
  double lo = f[0], hi = f[0];
  for (double v : f) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  r.data_range = (hi - lo) / static_cast<double>(f.size() - 1);
  for (std::size_t i = 0; i < h.size(); ++i) r.grids.push_back({h[i], f[i], f[i], 0.0, 0.0});
  r.grids.front().rde = rde_finest;
  return r;
}

const std::vector<double> kH5{0.5, 0.75, 1.0, 1.5, 2.0};
const std::vector<double> kF5{1018, 1019, 1020, 1022, 1024};  // R_f = 6/4 = 1.5

TEST(ExtrapVerdict, AllRulesMetIsConverged) {
  const Verdict v = judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.01), {});
  EXPECT_EQ(v.value, "converged");
  EXPECT_FALSE(v.next_h);
  EXPECT_EQ(v.checks.dof, 2);
  EXPECT_TRUE(v.checks.inside_envelope);
}

TEST(ExtrapVerdict, EnvelopeEdgesAreInsideAndBeyondIsUnreliable) {
  // Envelope [1018 − 3·1.5, 1024 + 3·1.5] = [1013.5, 1028.5].
  // The upper edge is tested on data that are not monotone (kF5 fall with
  // every refinement, so any f0 above its finest value 1018 lies behind the
  // trend, see MonotoneDataWithF0BehindTheTrendAreUnreliable); same range.
  const std::vector<double> zigzag{1018, 1019, 1018.5, 1022, 1024};
  EXPECT_EQ(judge(fitted(kH5, kF5, 1013.5, 1.2, 0.3, 0.01), {}).value, "converged");
  EXPECT_EQ(judge(fitted(kH5, zigzag, 1028.5, 1.2, 0.3, 0.01), {}).value, "converged");
  const Verdict low = judge(fitted(kH5, kF5, 1013.4, 1.2, 0.3, 0.01), {});
  EXPECT_EQ(low.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(low, "outside the data envelope [1013.5, 1028.5]")) << low.reasons.front();
  EXPECT_DOUBLE_EQ(*low.checks.envelope_low, 1013.5);
  EXPECT_DOUBLE_EQ(*low.checks.envelope_high, 1028.5);
  EXPECT_EQ(judge(fitted(kH5, zigzag, 1028.6, 1.2, 0.3, 0.01), {}).value, "unreliable");
}

// The converged reason says where f0 lies: within [min f, max f], or how far
// beyond the data (then within k R_f), never "inside the data envelope" for
// an f0 beyond every data point.
TEST(ExtrapVerdict, ConvergedReasonStatesWhereF0Lies) {
  const Verdict below = judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.01), {});
  ASSERT_EQ(below.value, "converged");
  EXPECT_TRUE(any_reason_contains(below, "f0 lies 1 below the smallest value 1018 (0.6667 R_f), within the "
                                         "envelope of 3 R_f")) << below.reasons.front();
  EXPECT_FALSE(any_reason_contains(below, "inside the data envelope"));
  // The trial's case: data zigzag up to 1015.6, f0 = 1016.4 above all of them.
  const std::vector<double> f{1015.6, 1014.9, 1015.3, 1014.1, 1013.7};
  const Verdict above = judge(fitted(kH5, f, 1016.4, 1.2, 0.3, 0.01), {});
  ASSERT_EQ(above.value, "converged") << above.reasons.front();
  EXPECT_TRUE(any_reason_contains(above, "f0 lies 0.8 above the largest value 1015.6")) << above.reasons.front();
  const std::vector<double> g{1018, 1019, 1017, 1022, 1024};
  const Verdict inside = judge(fitted(kH5, g, 1017.5, 1.2, 0.3, 0.01), {});
  ASSERT_EQ(inside.value, "converged") << inside.reasons.front();
  EXPECT_TRUE(any_reason_contains(inside, "f0 lies within the data range [1017, 1024]"));
}

// The two sentences whose arithmetic looked wrong: each value is
// quoted to the decimal U supports (two significant digits of U), the
// distance taken between the quoted values, so the printed numbers add up.
TEST(ExtrapVerdict, SentencesQuoteTheDigitsOfFZeroPlusMinusU) {
  // f0 = 1016.98 ± 1.4637 prints "1017.0 ± 1.5"; the largest value 1015.855
  // prints "1015.9" and 1017.0 − 1015.9 = 1.1 (never "1.14 above 1016").
  const std::vector<double> up{1015.855, 1015.2, 1014.9, 1014.1, 1013.7};
  ExtrapolationResult r = fitted(kH5, up, 1016.98, 1.2, 0.3, 0.01);
  r.u0 = 1.4637;
  Verdict v = judge(r, {});
  ASSERT_EQ(v.value, "converged") << v.reasons.front();
  EXPECT_TRUE(any_reason_contains(v, "f0 lies 1.1 above the largest value 1015.9 (")) << v.reasons.front();
  // f0 = 1003.004 ± 0.47 prints "1003.00 ± 0.47"; the smallest value 1003.43:
  // "0.43 below the smallest value 1003.43" (never "0.4262 below … 1003").
  const std::vector<double> down{1003.43, 1003.9, 1004.2, 1004.9, 1005.6};
  r = fitted(kH5, down, 1003.004, 1.2, 0.3, 0.01);
  r.u0 = 0.47;
  v = judge(r, {});
  ASSERT_EQ(v.value, "converged") << v.reasons.front();
  EXPECT_TRUE(any_reason_contains(v, "f0 lies 0.43 below the smallest value 1003.43 (")) << v.reasons.front();
  // Without U₀ the finest grid's U₁ gives the digits; an f0 beyond the
  // envelope quotes f0 and the envelope's edges with them.
  r = fitted(kH5, kF5, 1013.4123, 1.2, 0.3, 0.01);
  r.grids.front().u = 0.0712;  // two digits: 0.071, values to 3 decimals
  v = judge(r, {});
  ASSERT_EQ(v.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(v, "f0 = 1013.412 lies outside the data envelope [1013.500, 1028.500]"))
      << v.reasons.front();
}

// The next-grid advice names the cell size in the case's own symbol.
TEST(ExtrapVerdict, NextGridAdviceUsesTheCasesSymbol) {
  ExtrapolationResult r = fitted(kH5, kF5, 1017.0, 2.5, 0.3, 0.01);
  EXPECT_TRUE(any_reason_contains(judge(r, {}), "add the next finer grid Δ* = "));
  ExtrapolationOptions external;
  external.h_symbol = "h";
  const Verdict v = judge(r, external);
  EXPECT_TRUE(any_reason_contains(v, "add the next finer grid h = 0.3536 (")) << v.reasons.back();
  EXPECT_FALSE(any_reason_contains(v, "Δ*"));
}

// Data changing with one sign on every refinement (≥ 3 differences) and an
// f0 on the wrong side of the finest value: unreliable.
TEST(ExtrapVerdict, MonotoneDataWithF0BehindTheTrendAreUnreliable) {
  // kF5 fall with every refinement (1024 → 1018): f0 above 1018 is behind.
  const Verdict fall = judge(fitted(kH5, kF5, 1019.0, 1.2, 0.3, 0.01), {});
  EXPECT_EQ(fall.value, "unreliable");
  EXPECT_TRUE(fall.checks.monotone);
  EXPECT_TRUE(fall.checks.behind_trend);
  EXPECT_TRUE(any_reason_contains(fall, "the data fall with every refinement (4 grid-to-grid differences of one "
                                        "sign) but f0 = 1019 lies above the finest value 1018"))
      << fall.reasons.front();
  // Rising with refinement, f0 below the finest value.
  const std::vector<double> rise{1024, 1022, 1020, 1019, 1018};
  const Verdict r = judge(fitted(kH5, rise, 1023.0, 1.2, 0.3, 0.01), {});
  EXPECT_EQ(r.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(r, "rise with every refinement")) << r.reasons.front();
  // Ahead of the trend (or at the finest value) is fine.
  EXPECT_EQ(judge(fitted(kH5, rise, 1025.0, 1.2, 0.3, 0.01), {}).value, "converged");
  EXPECT_EQ(judge(fitted(kH5, kF5, 1018.0, 1.2, 0.3, 0.01), {}).value, "converged");
  // A zigzag is not monotone: the rule does not apply.
  const Verdict z = judge(fitted(kH5, {1018, 1019, 1018.5, 1022, 1024}, 1019.0, 1.2, 0.3, 0.01), {});
  EXPECT_EQ(z.value, "converged");
  EXPECT_FALSE(z.checks.monotone);
  // Two differences are not enough to call a trend (n = 3: insufficient anyway, via judge's n < 4 rule).
}

// With fewer than 2 degrees of freedom σ_RE/R_f < 1 is not a good fit: the
// fit cannot be judged.
TEST(ExtrapVerdict, OneDegreeOfFreedomCannotJudgeTheFit) {
  const std::vector<double> h{0.5, 1.0, 1.5, 2.0}, f{1018, 1020, 1019, 1024};
  const Verdict v = judge(fitted(h, f, 1017.0, 1.0, 0.1, 0.01), {});
  EXPECT_FALSE(v.checks.good_fit);
  EXPECT_TRUE(any_reason_contains(v, "the fit (σ_RE/R_f = 0.1) cannot be judged")) << v.reasons.front();
  EXPECT_FALSE(any_reason_contains(v, "does not describe the data"));
}

TEST(ExtrapVerdict, OneDegreeOfFreedomIsUnreliable) {
  const std::vector<double> h{0.5, 1.0, 1.5, 2.0}, f{1018, 1020, 1022, 1024};
  const Verdict v = judge(fitted(h, f, 1017.0, 1.0, 0.1, 0.01), {});
  EXPECT_EQ(v.value, "unreliable");
  EXPECT_EQ(v.checks.dof, 1);
  EXPECT_TRUE(any_reason_contains(v, "1 degree(s) of freedom"));
}

TEST(ExtrapVerdict, FinestRdeLimits) {
  EXPECT_EQ(judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.05), {}).value, "converged");  // = limit
  const Verdict pre = judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.0501), {});
  EXPECT_EQ(pre.value, "pre-asymptotic");
  EXPECT_TRUE(any_reason_contains(pre, "RDE 5.01% exceeds 5%"));
  EXPECT_EQ(judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.25), {}).value, "pre-asymptotic");
  const Verdict bad = judge(fitted(kH5, kF5, 1017.0, 1.2, 0.3, 0.2501), {});
  EXPECT_EQ(bad.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(bad, "exceeds 25%"));
}

TEST(ExtrapVerdict, OrderOutsideRangeOrMissingIsPreAsymptoticWithNextGrid) {
  ExtrapolationResult r = fitted(kH5, kF5, 1017.0, 2.5, 0.3, 0.01);
  r.method = "mixed";
  const Verdict v = judge(r, {});
  EXPECT_EQ(v.value, "pre-asymptotic");
  EXPECT_TRUE(any_reason_contains(v, "p = 2.5 is outside the accepted range [0.5, 2.1]"));
  // Mean ratio (2/0.5)^(1/4) = √2: next grid 0.5/√2.
  ASSERT_TRUE(v.next_h);
  EXPECT_NEAR(*v.next_h, 0.5 / std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(any_reason_contains(v, "Δ* = 0.3536"));
  r.p.reset();
  EXPECT_TRUE(any_reason_contains(judge(r, {}), "no observed order p was found"));
  // The accepted range is the caller's.
  ExtrapolationOptions wide;
  wide.p_high = 3.0;
  EXPECT_EQ(judge(fitted(kH5, kF5, 1017.0, 2.5, 0.3, 0.01), wide).value, "converged");
}

TEST(ExtrapVerdict, PoorFitIsNotConverged) {
  const Verdict v = judge(fitted(kH5, kF5, 1017.0, 1.2, 1.0, 0.01), {});
  EXPECT_EQ(v.value, "pre-asymptotic");
  EXPECT_TRUE(any_reason_contains(v, "σ_RE/R_f = 1 ≥ 1"));
}

TEST(ExtrapVerdict, FewerThanFourGridsIsInsufficient) {
  const ExtrapolationResult r = extrapolate({1.0, 1.5, 2.0}, {1020, 1022, 1024});
  EXPECT_EQ(r.verdict.value, "insufficient_grids");
  ASSERT_TRUE(r.verdict.next_h);
  EXPECT_NEAR(*r.verdict.next_h, 1.0 / std::sqrt(2.0), 1e-12);
  EXPECT_EQ(verdict_without_fit(0, "x").value, "insufficient_grids");
  EXPECT_EQ(verdict_without_fit(5, "the extrapolation failed").value, "unreliable");
}

TEST(ExtrapVerdict, ConstantDataAreConverged) {
  const ExtrapolationResult r = extrapolate(kH5, std::vector<double>(5, 1017.0));
  EXPECT_EQ(r.verdict.value, "converged");
}

// Exact f = 1017 + 30 h^1.3 on Δ* 0.5 … 2 (ratio √2): the power fit recovers
// p = 1.3 and f0 = 1017, σ ≈ 0; U_1 = 1.25·30·0.5^1.3 = 15.2, RDE_1 = 1.5 %;
// f0 is 0.79 R_f below min f (R_f = 30(2^1.3 − 0.5^1.3)/4 = 15.4).
TEST(ExtrapVerdict, ExactPowerLawInTheAsymptoticRangeIsConverged) {
  std::vector<double> f;
  for (double h : kH5) f.push_back(1017 + 30 * std::pow(h, 1.3));
  const ExtrapolationResult r = extrapolate(kH5, f, test::formula_of(ExtrapolationMethod::kCapped));
  EXPECT_EQ(r.verdict.value, "converged") << r.verdict.reasons.front();
  EXPECT_NEAR(*r.verdict.checks.rde_finest, 1.25 * 30 * std::pow(0.5, 1.3) / 1017, 1e-6);
}

// f = 1017 + 10 h seen only on Δ* 2 … 4 (five grids, ratio 2^(1/4)): the fit
// is exact (p = 1, f0 = 1017) and RDE_1 = 1.25·20/1017 = 2.5 %, but f0 lies
// d = (n − 1)/(ρ^p − 1) = 4/(2 − 1) = 4 R_f below the data, beyond k = 3:
// unreliable — the grids do not span enough of the asymptotic range.
TEST(ExtrapVerdict, NarrowSpanExtrapolatesTooFarEvenForExactData) {
  std::vector<double> h, f;
  for (int i = 0; i < 5; ++i) {
    h.push_back(2.0 * std::pow(2.0, i / 4.0));
    f.push_back(1017 + 10 * h.back());
  }
  const ExtrapolationResult r = extrapolate(h, f);
  EXPECT_NEAR(*r.f0, 1017, 1e-6);
  EXPECT_NEAR(*r.p, 1.0, 1e-6);
  EXPECT_EQ(r.verdict.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(r.verdict, "outside the data envelope"));
}

// The coarse study: four grids Δ* 4 → 2 with dp* from 1000.8 to
// 1034.3 rising as the grid is refined, extrapolated far above the data.
// Whatever f0 the fit gives, four grids leave one degree of freedom.
TEST(ExtrapVerdict, FourCoarseGridsAreNeverConverged) {
  const ExtrapolationResult r = extrapolate({2.0, 2.5, 3.333, 4.0}, {1034.3, 1023.9, 1010.2, 1000.8});
  EXPECT_EQ(r.verdict.value, "unreliable");
  EXPECT_TRUE(any_reason_contains(r.verdict, "degree(s) of freedom"));
  const auto j = to_json(r);
  EXPECT_EQ(j["verdict"]["value"], "unreliable");
  EXPECT_EQ(j["status"], "ok");  // the fit itself was made
}

}  // namespace
}  // namespace gridfree
