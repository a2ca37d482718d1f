// SPDX-License-Identifier: GPL-3.0-or-later
// The default (Fullmer & Musser 2018, PHYSICS.md §8) procedure through the
// public API extrapolate(h, f, opts) with --method fm: method choice, σ_RE, Fs, U and RDE
// recomputed independently from the reported fits, invariances, and the
// special cases (constant data, fewer than 4 grids).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "extrap/extrapolation.h"
#include "expect_relative.h"
#include "extrap_test_data.h"

namespace gridfree {
namespace {

using test_support::expect_rel;

// PHYSICS.md §8 recomputed from the reported f̂: σ_RE, R_f, Fs, U_i, RDE_i.
void expect_fm_uncertainties_consistent(const std::vector<double>& h_in, const ExtrapolationResult& r) {
  const std::size_t n = r.grids.size();
  double W = 0;
  for (const auto& g : r.grids) W += 1 / g.h;
  double sum = 0, fmin = r.grids[0].f, fmax = fmin;
  for (const auto& g : r.grids) {
    sum += n * (1 / g.h / W) * std::pow(g.f - *g.fhat, 2);
    fmin = std::min(fmin, g.f);
    fmax = std::max(fmax, g.f);
  }
  const double sigma = std::sqrt(sum / (n - 3));
  const double range = (fmax - fmin) / (n - 1);
  const double fs = std::max(1.25, 3 * sigma / range);
  ASSERT_EQ(n, h_in.size());
  expect_rel(*r.sigma_re, sigma, 1e-9);
  expect_rel(*r.data_range, range, 1e-14);
  expect_rel(*r.fs, fs, 1e-9);
  expect_rel(*r.sigma_over_range, sigma / range, 1e-9);
  for (const auto& g : r.grids) {
    const double u = fs * std::fabs(*r.f0 - g.f) + sigma;
    EXPECT_NEAR(*g.u, u, 1e-9 * std::max(1.0, u));
    EXPECT_NEAR(*g.rde, u / std::fabs(*r.f0), 1e-12);
  }
}

TEST(ExtrapFm, PowerLawInRangeIsChosen) {
  for (double p : {0.7, 1.0, 1.9}) {
    const auto h = test::default_h();
    const auto r = test::extrapolate_fm(h, test::power_law(h, 1158.8, -0.45, p));
    EXPECT_EQ(r.status, "ok");
    EXPECT_EQ(*r.method, "power") << "p = " << p;
    expect_rel(*r.f0, 1158.8, 1e-10);
    expect_rel(*r.p, p, 1e-10);
    expect_rel(*r.power->c, -0.45, 1e-10);
    EXPECT_TRUE(*r.power->p_found);
    // Exact data: σ_RE ≈ 0, Fs = 1.25, U_i = 1.25|f0 − f_i|.
    EXPECT_LT(*r.sigma_re, 1e-9);
    EXPECT_DOUBLE_EQ(*r.fs, 1.25);
    for (const auto& g : r.grids) EXPECT_NEAR(*g.u, 1.25 * std::fabs(1158.8 - g.f), 1e-8);
  }
}

TEST(ExtrapFm, OrdersOutsideTheRangeFallToMixed) {
  for (double p : {3.0, -0.5, 0.3}) {
    const auto h = test::default_h();
    const auto r = test::extrapolate_fm(h, test::power_law(h, 1158.8, 0.2, p));
    EXPECT_EQ(*r.method, "mixed") << "p = " << p;
    expect_rel(*r.power->p, p, 1e-10);  // the power fit itself is still exact
    expect_rel(*r.power->f0, 1158.8, 1e-10);
    EXPECT_EQ(*r.f0, *r.mixed->f0);
    expect_fm_uncertainties_consistent(h, r);
  }
}

TEST(ExtrapFm, PRangeOptionMovesTheBoundary) {
  const auto h = test::default_h();
  const auto f = test::power_law(h, 10.0, 1.0, 3.0);
  ExtrapolationOptions opts;
  opts.p_high = 3.5;
  EXPECT_EQ(*test::extrapolate_fm(h, f, opts).method, "power");
  opts.p_low = 3.2;
  EXPECT_EQ(*test::extrapolate_fm(h, f, opts).method, "mixed");
}

TEST(ExtrapFm, ExactMixedDataGiveBackCoefficients) {
  const auto h = test::default_h();
  const auto r = test::extrapolate_fm(h, test::mixed_law(h, 1158.8, 0.31, -0.052));
  expect_rel(*r.mixed->f0, 1158.8, 1e-10);
  expect_rel(*r.mixed->c1, 0.31, 1e-10);
  expect_rel(*r.mixed->c2, -0.052, 1e-10);
  EXPECT_LT(*r.mixed->sigma, 1e-9);
}

TEST(ExtrapFm, UncertaintiesFollowPhysicsSection8) {
  const auto h = test::oscillatory_h();
  const auto r = test::extrapolate_fm(h, test::oscillatory_f(h));
  expect_fm_uncertainties_consistent(h, r);
  // The chosen fit's own σ is the σ_RE.
  EXPECT_EQ(*r.sigma_re, *r.method == "power" ? *r.power->sigma : *r.mixed->sigma);
}

TEST(ExtrapFm, InvariantUnderScalingOfH) {
  // h -> 1000 h: f0, p, σ, U unchanged; c ~ k^−p, c1 ~ 1/k, c2 ~ 1/k².
  const auto h = test::oscillatory_h();
  const auto f = test::oscillatory_f(h);
  std::vector<double> hk;
  for (double hi : h) hk.push_back(1000 * hi);
  const auto a = test::extrapolate_fm(h, f), b = test::extrapolate_fm(hk, f);
  EXPECT_EQ(*a.method, *b.method);
  expect_rel(*b.f0, *a.f0, 1e-12);
  expect_rel(*b.power->p, *a.power->p, 1e-9);
  expect_rel(*b.sigma_re, *a.sigma_re, 1e-8);
  expect_rel(*b.power->c, *a.power->c * std::pow(1000.0, -*a.power->p), 1e-8);
  expect_rel(*b.mixed->c1, *a.mixed->c1 / 1000, 1e-9);
  expect_rel(*b.mixed->c2, *a.mixed->c2 / 1e6, 1e-9);
  for (std::size_t i = 0; i < h.size(); ++i) expect_rel(*b.grids[i].u, *a.grids[i].u, 1e-8);
}

TEST(ExtrapFm, InvariantUnderInputOrder) {
  const auto h = test::oscillatory_h();
  const auto f = test::oscillatory_f(h);
  std::vector<std::size_t> idx(h.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::shuffle(idx.begin(), idx.end(), std::mt19937(42));
  std::vector<double> hs, fs;
  for (auto i : idx) hs.push_back(h[i]), fs.push_back(f[i]);
  const auto a = test::extrapolate_fm(h, f), b = test::extrapolate_fm(hs, fs);
  EXPECT_EQ(*a.f0, *b.f0);
  EXPECT_EQ(*a.power->p, *b.power->p);
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_EQ(b.grids[i].h, h[i]);  // reported finest first
    EXPECT_EQ(*a.grids[i].u, *b.grids[i].u);
  }
}

TEST(ExtrapFm, ConstantDataHaveZeroUncertainty) {
  const auto r = test::extrapolate_fm({0.5, 1, 2, 4, 8}, {3.25, 3.25, 3.25, 3.25, 3.25});
  EXPECT_EQ(r.status, "ok");
  EXPECT_EQ(*r.method, "constant");
  EXPECT_EQ(*r.f0, 3.25);
  EXPECT_EQ(*r.data_range, 0.0);
  EXPECT_FALSE(r.sigma_over_range.has_value());
  for (const auto& g : r.grids) {
    EXPECT_EQ(*g.u, 0.0);
    EXPECT_EQ(*g.rde, 0.0);
  }
  for (const auto& t : r.gci) EXPECT_EQ(t.status, "zero_difference");
}

TEST(ExtrapFm, ThreeGridsAreInsufficientButGciIsComputed) {
  const auto r = test::extrapolate_fm({1, 2, 4}, {1.1, 1.4, 2.6});
  EXPECT_EQ(r.status, "insufficient_grids");
  EXPECT_FALSE(r.method.has_value());
  EXPECT_FALSE(r.f0.has_value());
  EXPECT_FALSE(r.sigma_re.has_value());
  EXPECT_FALSE(r.fs.has_value());
  for (const auto& g : r.grids) EXPECT_FALSE(g.u.has_value());
  ASSERT_EQ(r.gci.size(), 1u);
  EXPECT_EQ(r.gci[0].status, "ok");
  // r = 2, ε32/ε21 = 1.2/0.3 = 4: p = 2, φ_ext = (4·1.1 − 1.4)/3 = 1.0.
  EXPECT_NEAR(*r.gci[0].p, 2.0, 1e-12);
  EXPECT_NEAR(*r.gci[0].f_ext, 1.0, 1e-12);
  EXPECT_EQ(test::extrapolate_fm({1, 2}, {1, 2}).gci.size(), 0u);
}

TEST(ExtrapFm, SigmaOverRangeFlagsAPoorFit) {
  // Pure alternation has no trend at all: the fit cannot follow it.
  const auto h = test::default_h();
  std::vector<double> f;
  for (std::size_t i = 0; i < h.size(); ++i) f.push_back(i % 2 ? 1.0 : -1.0);
  const auto r = test::extrapolate_fm(h, f);
  EXPECT_GT(*r.sigma_over_range, 1.0);
  EXPECT_GT(*r.fs, 1.25);
  expect_fm_uncertainties_consistent(h, r);
}

TEST(ExtrapFm, RejectsBadInputAndOptions) {
  EXPECT_THROW(extrapolate({1, 2, 2, 3}, {1, 2, 3, 4}), InputError);
  EXPECT_THROW(extrapolate({1, 2, NAN, 3}, {1, 2, 3, 4}), InputError);
  ExtrapolationOptions opts;
  opts.p_low = 2;
  opts.p_high = 1;
  EXPECT_THROW(extrapolate({1, 2, 3, 4}, {1, 2, 3, 5}, opts), InputError);
  EXPECT_THROW(parse_method("gci", "--method"), InputError);
}

}  // namespace
}  // namespace gridfree
