// SPDX-License-Identifier: GPL-3.0-or-later
// Drag laws (PHYSICS.md §4) against values computed independently here.
//
// 1. A long-double transcription of PHYSICS.md written in the other form:
//    Wen & Yu through C_d, BVK and HKL through F with the raw Re powers,
//    Syamlal & O'Brien through the Dalla Valle C_d. Tolerance 1e-12 relative:
//    each law is ~20 double operations whose rounding (~1e-16 each, pow()
//    within 1 ulp) stays far below it, while a wrong constant or exponent
//    changes the value by far more.
// 2. The table of docs/DRAG_LAWS.md, D* = D d²/μ_g at (φ, Re_s), computed
//    separately (double precision, formulas as printed) and given there to 10
//    significant digits: tolerance 1e-9 relative.
// 3. Limits and continuity: Re = 0, the Stokes limit, branch switches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "drag/drag_law.h"

namespace gridfree {
namespace {

using Real = long double;

// Gas of the SSCP-like case (air, 3.256 mm beads): the tests use (φ, Re_s).
constexpr double kRho = 1.2e-3, kMu = 1.8e-4, kD = 0.3256;

DragState state_at(double phi, double re_s, double d = kD, double rho = kRho, double mu = kMu) {
  DragState s;
  s.eps_g = 1.0 - phi;
  s.slip = re_s * mu / (s.eps_g * rho * d);
  s.d = d;
  s.rho_g = rho;
  s.mu_g = mu;
  return s;
}

struct Ref {
  Real eps, phi, slip, d, rho, mu, re;
  explicit Ref(const DragState& s)
      : eps(s.eps_g), phi(1.0L - eps), slip(s.slip), d(s.d), rho(s.rho_g), mu(s.mu_g),
        re(eps * rho * slip * d / mu) {}
};

Real ref_wen_yu(const Ref& r) {
  const Real cd = r.re <= 1000 ? 24.0L / r.re * (1.0L + 0.15L * std::pow(r.re, 0.687L)) : 0.44L;
  return 0.75L * cd * r.rho * r.eps * r.slip * std::pow(r.eps, -2.65L) / r.d;
}
Real ref_ergun(const Ref& r) {
  return 150.0L * r.phi * r.mu / (r.eps * r.d * r.d) + 1.75L * r.rho * r.slip / r.d;
}
Real ref_gidaspow(const Ref& r) { return r.eps <= 0.8L ? ref_ergun(r) : ref_wen_yu(r); }
Real ref_blend(const Ref& r) {
  const Real psi = std::atan(150.0L * 1.75L * (r.eps - 0.8L)) / std::numbers::pi_v<Real> + 0.5L;
  return (1 - psi) * ref_ergun(r) + psi * ref_wen_yu(r);
}
Real ref_bvk_f(Real phi, Real re) {
  const Real e = 1 - phi;
  return 10 * phi / (e * e) + e * e * (1 + 1.5L * std::sqrt(phi)) +
         0.413L * re / (24 * e * e) * (1 / e + 3 * e * phi + 8.4L * std::pow(re, -0.343L)) /
             (1 + std::pow(10.0L, 3 * phi) * std::pow(re, -(1 + 4 * phi) / 2));
}
Real ref_bvk(const Ref& r) { return 18 * r.mu * r.eps * ref_bvk_f(r.phi, r.re) / (r.d * r.d); }

struct RefHkl {
  Real f0 = 0, f1 = 0, f2 = 0, f3 = 0, t1 = 0, t2 = 0;
};
RefHkl ref_hkl_terms(Real phi) {
  RefHkl h;
  const Real w = std::exp(-10 * (0.4L - phi) / phi);
  const Real dense = 10 * phi / std::pow(1 - phi, 3);
  const Real common = 1 + 3 * std::sqrt(phi / 2) + 135.0L / 64 * phi * std::log(phi);
  h.f0 = phi < 0.4L ? (1 - w) * (common + 17.14L * phi) /
                              (1 + 0.681L * phi - 8.48L * phi * phi + 8.16L * phi * phi * phi) + w * dense
                    : dense;
  h.f1 = phi <= 0.1L ? std::sqrt(2 / phi) / 40 : 0.11L + 5.1e-4L * std::exp(11.6L * phi);
  h.f2 = phi < 0.4L ? (1 - w) * (common + 17.89L * phi) /
                              (1 + 0.681L * phi - 11.03L * phi * phi + 15.41L * phi * phi * phi) + w * dense
                    : dense;
  h.f3 = phi < 0.0953L ? 0.9351L * phi + 0.03667L : 0.0673L + 0.212L * phi + 0.0232L / std::pow(1 - phi, 5);
  h.t1 = (h.f2 - 1) / (0.375L - h.f3);
  h.t2 = (h.f3 + std::sqrt(h.f3 * h.f3 - 4 * h.f1 * (h.f0 - h.f2))) / (2 * h.f1);
  return h;
}
Real ref_hkl_f(Real phi, Real re_h) {
  const RefHkl h = ref_hkl_terms(phi);
  if (phi <= 0.01L && re_h <= h.t1) return 1 + 0.375L * re_h;
  if (phi > 0.01L && re_h <= h.t2) return h.f0 + h.f1 * re_h * re_h;
  return h.f2 + h.f3 * re_h;
}
Real ref_hkl(const Ref& r) { return 18 * r.mu * r.eps * r.eps * ref_hkl_f(r.phi, r.re / 2) / (r.d * r.d); }

Real ref_syamlal(const Ref& r) {
  const Real re = r.rho * r.slip * r.d / r.mu;
  const Real a = std::pow(r.eps, 4.14L);
  const Real b = r.eps <= 0.85L ? 0.8L * std::pow(r.eps, 1.28L) : std::pow(r.eps, 2.65L);
  const Real vr = (a - 0.06L * re + std::sqrt(0.0036L * re * re + 0.12L * re * (2 * b - a) + a * a)) / 2;
  const Real re_r = re / vr;
  const Real cd = std::pow(0.63L + 4.8L / std::sqrt(re_r), 2);  // Dalla Valle
  return 0.75L * r.eps * cd * r.rho * r.slip / (vr * vr * r.d);
}

Real reference(DragLaw law, const DragState& s) {
  const Ref r(s);
  switch (law) {
    case DragLaw::kWenYu: return ref_wen_yu(r);
    case DragLaw::kGidaspow: return ref_gidaspow(r);
    case DragLaw::kGidaspowBlend: return ref_blend(r);
    case DragLaw::kBvk: return ref_bvk(r);
    case DragLaw::kHkl: return ref_hkl(r);
    case DragLaw::kSyamlalObrien: return ref_syamlal(r);
  }
  return 0;
}

const std::vector<DragLaw> kAllLaws = {DragLaw::kWenYu, DragLaw::kGidaspow,       DragLaw::kGidaspowBlend,
                                       DragLaw::kBvk,   DragLaw::kHkl, DragLaw::kSyamlalObrien};

TEST(DragLaw, MatchesIndependentTranscription) {
  const double phis[] = {0.003, 0.03, 0.08, 0.15, 0.25, 0.38, 0.42, 0.55};
  const double res[] = {1e-3, 0.7, 8.0, 60.0, 400.0, 1500.0};
  for (DragLaw law : kAllLaws)
    for (double phi : phis)
      for (double re : res) {
        const DragState s = state_at(phi, re);
        const double expected = static_cast<double>(reference(law, s));
        EXPECT_NEAR(drag_coefficient(law, s), expected, 1e-12 * expected)
            << drag_law_name(law) << " phi=" << phi << " Re=" << re;
      }
}

// docs/DRAG_LAWS.md table: D* = D d²/μ_g for wen_yu, gidaspow, gidaspow_blend,
// bvk, hkl, syamlal_obrien.
struct TableRow {
  double phi, re;
  double d_star[6];
};
const TableRow kTable[] = {
    {0.005, 0, {18.2406932988, 18.2406932988, 18.1319645474, 20.5165637981, 17.82045, 17.554128154}},
    {0.005, 1, {20.9767972937, 20.9767972937, 20.8619919049, 21.9574911493, 21.161784375, 22.5211849186}},
    {0.005, 50, {58.4498526236, 58.4498526236, 58.6378988678, 64.3897786338, 39.4457872753, 65.5239723734}},
    {0.005, 500, {213.820941602, 213.820941602, 217.963991953, 321.317430155, 205.224755757, 273.591055469}},
    {0.05, 0, {20.620773459, 20.620773459, 20.517917518, 30.0827359225, 32.292046932, 20.2997933817}},
    {0.05, 1, {23.7138894779, 23.7138894779, 23.6009224636, 31.3795107265, 32.9341869393, 26.6620225694}},
    {0.05, 50, {66.07649994, 66.07649994, 66.3506806317, 78.7803941181, 66.9522631149, 78.525454359}},
    {0.05, 500, {241.720702462, 241.720702462, 247.27509049, 375.670325776, 371.88106624, 336.529569923}},
    {0.2, 0, {32.5150210553, 37.5, 35.0075105277, 60.3982807442, 62.7601568431, 34.8209951755}},
    {0.2, 1, {37.3922742136, 39.6875, 38.5398871068, 61.1857035333, 63.0919028735, 48.4824917333}},
    {0.2, 50, {104.190019403, 146.875, 125.532509702, 128.388231071, 120.23061951, 135.181403571}},
    {0.2, 500, {381.1473777, 1131.25, 756.19868885, 580.546202752, 588.08864451, 635.444694045}},
    {0.45, 0, {87.7629833581, 122.727272727, 122.557693791, 153.280886332, 147.272727273, 112.928846766}},
    {0.45, 1, {100.927430862, 125.909090909, 125.787928334, 153.544827877, 147.550853018, 99.2774148692}},
    {0.45, 50, {281.224696839, 281.818181818, 281.81530338, 275.743621171, 232.170076944, 257.820580118}},
    {0.45, 500, {1028.77469798, 1713.63636364, 1710.31474279, 1151.26646276, 996.246223986, 1445.36376842}},
};

TEST(DragLaw, MatchesDocumentedTable) {
  for (const auto& row : kTable)
    for (std::size_t l = 0; l < kAllLaws.size(); ++l) {
      const DragState s = state_at(row.phi, row.re);
      const double d_star = drag_coefficient(kAllLaws[l], s) * s.d * s.d / s.mu_g;
      EXPECT_NEAR(d_star, row.d_star[l], 1e-9 * row.d_star[l])
          << drag_law_name(kAllLaws[l]) << " phi=" << row.phi << " Re=" << row.re;
    }
}

TEST(DragLaw, ZeroSlipIsFinitePositiveAndTheLimit) {
  for (DragLaw law : kAllLaws)
    for (double phi : {0.0, 0.004, 0.05, 0.2, 0.45, 0.62}) {
      const DragState s0 = state_at(phi, 0.0);
      const double d0 = drag_coefficient(law, s0);
      EXPECT_TRUE(std::isfinite(d0)) << drag_law_name(law) << " phi=" << phi;
      EXPECT_GT(d0, 0.0) << drag_law_name(law) << " phi=" << phi;
      // Re = 1e-16: the slowest Re-dependent term is Syamlal & O'Brien's
      // 0.63 √(Re_i/V_r), ~1e-8/√A relative (≤ 4e-8 at φ = 0.62); tolerance 1e-6.
      const double d_small = drag_coefficient(law, state_at(phi, 1e-16));
      EXPECT_NEAR(d0, d_small, 1e-6 * d0) << drag_law_name(law) << " phi=" << phi;
    }
}

TEST(DragLaw, StokesLimitOfBvkAndHkl) {
  // φ → 0, Re → 0: F → 1, i.e. D d²/(18 μ ε_g) → 1 (BVK) and D d²/(18 μ ε_g²) → 1 (HKL).
  // At φ = 1e-8 the leading correction is BVK's 1.5 √φ = 1.5e-4; HKL's
  // dilute branch is 1 + 3/8 Re_h exactly. Tolerance 2e-4.
  const DragState s = state_at(1e-8, 1e-10);
  const double scale = 18.0 * s.mu_g / (s.d * s.d);
  EXPECT_NEAR(drag_coefficient(DragLaw::kBvk, s) / (scale * s.eps_g), 1.0, 2e-4);
  EXPECT_NEAR(drag_coefficient(DragLaw::kHkl, s) / (scale * s.eps_g * s.eps_g), 1.0, 2e-4);
  // Exactly at φ = 0, Re = 0 both are the single-sphere Stokes drag 18 μ / d²,
  // and so is Wen & Yu (C_d = 24/Re).
  const DragState s0 = state_at(0.0, 0.0);
  EXPECT_DOUBLE_EQ(drag_coefficient(DragLaw::kBvk, s0), scale);
  EXPECT_DOUBLE_EQ(drag_coefficient(DragLaw::kHkl, s0), scale);
  EXPECT_DOUBLE_EQ(drag_coefficient(DragLaw::kWenYu, s0), scale);
}

TEST(DragLaw, PositiveAndIncreasingWithSlip) {
  // D increases with |u − v| at fixed ε_g for every law except Syamlal &
  // O'Brien, whose D falls at low Re in dense beds (V_r rises from A = ε_g^4.14
  // towards B); for it the drag force D |u − v| increases.
  for (DragLaw law : kAllLaws)
    for (double eps_g : {0.38, 0.45, 0.6, 0.75, 0.8, 0.85, 0.95, 0.995, 1.0}) {
      double previous = -1, previous_force = -1;
      for (double slip = 1e-3; slip < 1e6; slip *= 1.25) {
        DragState s{eps_g, slip, kD, kRho, kMu};
        const double d = drag_coefficient(law, s);
        ASSERT_GT(d, 0.0);
        if (law == DragLaw::kSyamlalObrien) {
          EXPECT_GT(d * slip, previous_force) << "eps_g=" << eps_g << " slip=" << slip;
        } else {
          EXPECT_GT(d, previous) << drag_law_name(law) << " eps_g=" << eps_g << " slip=" << slip;
        }
        previous = d;
        previous_force = d * slip;
      }
    }
  // The Syamlal & O'Brien exception, at φ = 0.45 (see the docs table).
  EXPECT_LT(drag_coefficient(DragLaw::kSyamlalObrien, state_at(0.45, 1.0)),
            drag_coefficient(DragLaw::kSyamlalObrien, state_at(0.45, 0.0)));
}

TEST(DragLaw, GidaspowSwitchesAtPointEight) {
  for (double re : {0.3, 5.0, 300.0}) {
    DragState dense = state_at(0.2, re);
    dense.eps_g = 0.8;
    DragState dilute = dense;
    dilute.eps_g = std::nextafter(0.8, 1.0);
    const double ergun = static_cast<double>(ref_ergun(Ref(dense)));
    const double wen_yu = static_cast<double>(ref_wen_yu(Ref(dilute)));
    EXPECT_NEAR(drag_coefficient(DragLaw::kGidaspow, dense), ergun, 1e-12 * ergun);
    EXPECT_NEAR(drag_coefficient(DragLaw::kGidaspow, dilute), wen_yu, 1e-12 * wen_yu);
    EXPECT_GT(std::abs(ergun - wen_yu), 0.01 * ergun) << "the law jumps at 0.8";
  }
}

TEST(DragLaw, GidaspowBlendIsContinuousAtPointEight) {
  // ψ' = 262.5/π ≈ 84 at 0.8, so over ±1e-9 the blend moves by ~1e-7 of the
  // Ergun–Wen-Yu difference: tolerance 1e-6 relative. At 0.8, ψ = 1/2 exactly.
  for (double re : {0.3, 5.0, 300.0}) {
    DragState below = state_at(0.2, re), above = below, at = below;
    below.eps_g = 0.8 - 1e-9;
    above.eps_g = 0.8 + 1e-9;
    at.eps_g = 0.8;
    const double lo = drag_coefficient(DragLaw::kGidaspowBlend, below);
    const double hi = drag_coefficient(DragLaw::kGidaspowBlend, above);
    EXPECT_NEAR(lo, hi, 1e-6 * lo);
    const Ref r(at);
    const double mid = static_cast<double>((ref_ergun(r) + ref_wen_yu(r)) / 2);
    EXPECT_NEAR(drag_coefficient(DragLaw::kGidaspowBlend, at), mid, 1e-12 * mid);
  }
}

// D of HKL at (φ, Re_h).
double hkl_at(double phi, double re_h) {
  return drag_coefficient(DragLaw::kHkl, state_at(phi, 2.0 * re_h));
}

TEST(DragLaw, HklContinuousAcrossReynoldsTransitions) {
  // Re_t1 and Re_t2 are where the two Re-branches meet, so F is continuous
  // there; over Re_h (1 ± 1e-9) F changes by ~1e-9 relative: tolerance 1e-7.
  for (double phi : {0.002, 0.006, 0.0099}) {
    const double t1 = static_cast<double>(ref_hkl_terms(phi).t1);
    EXPECT_NEAR(hkl_at(phi, t1 * (1 - 1e-9)), hkl_at(phi, t1 * (1 + 1e-9)), 1e-7 * hkl_at(phi, t1));
  }
  for (double phi : {0.02, 0.09, 0.12, 0.3, 0.39, 0.5, 0.6}) {
    const double t2 = static_cast<double>(ref_hkl_terms(phi).t2);
    EXPECT_NEAR(hkl_at(phi, t2 * (1 - 1e-9)), hkl_at(phi, t2 * (1 + 1e-9)), 1e-7 * hkl_at(phi, t2));
  }
}

TEST(DragLaw, HklAcrossSolidsFractionSwitches) {
  // D = 18 μ ε_g² F / d²; compare F on both sides via D/ε_g² at φ ± 1e-9.
  auto f_at = [](double phi, double re_h) {
    const DragState s = state_at(phi, 2.0 * re_h);
    return drag_coefficient(DragLaw::kHkl, s) * s.d * s.d / (18.0 * s.mu_g * s.eps_g * s.eps_g);
  };
  const double eps = 1e-9;
  for (double re_h : {0.0, 0.05, 1.0, 10.0, 100.0}) {
    // φ = 0.4: exactly continuous (w = 1 there, F0 = F2 = 10φ/(1−φ)³ on both sides).
    EXPECT_NEAR(f_at(0.4 - eps, re_h), f_at(0.4 + eps, re_h), 1e-6 * f_at(0.4, re_h)) << re_h;
    // φ = 0.1 (F1 switch) and φ = 0.0953 (F3 switch): not exactly continuous;
    // the jumps are 1.8e-4 in F1 and 2e-6 in F3, below 1e-3 of F.
    for (double phi_switch : {0.1, 0.0953}) {
      const double lo = f_at(phi_switch - eps, re_h), hi = f_at(phi_switch + eps, re_h);
      EXPECT_NEAR(lo, hi, 1e-3 * lo) << "phi=" << phi_switch << " Re_h=" << re_h;
      const double expected_jump =
          static_cast<double>(ref_hkl_f(phi_switch + eps, re_h) - ref_hkl_f(phi_switch - eps, re_h));
      EXPECT_NEAR(hi - lo, expected_jump, 1e-9 * lo);
    }
  }
  // φ = 0.01: a real jump of the correlation at low Re_h, from the Oseen law
  // 1 + 3/8 Re_h to F0 + F1 Re_h²; F0(0.01) ≈ 1.279, so ~28 % at Re_h = 0.
  const double lo = f_at(0.01 - eps, 0.0), hi = f_at(0.01 + eps, 0.0);
  EXPECT_NEAR(lo, 1.0, 1e-12);
  EXPECT_NEAR(hi, static_cast<double>(ref_hkl_terms(0.01 + eps).f0), 1e-9);
  EXPECT_GT(hi / lo, 1.27);
  // Above both transitions F = F2 + F3 Re_h on both sides: continuous again.
  EXPECT_NEAR(f_at(0.01 - eps, 50.0), f_at(0.01 + eps, 50.0), 1e-6 * f_at(0.01, 50.0));
}

TEST(DragLaw, RegistryRoundTrips) {
  EXPECT_EQ(drag_laws().size(), 6u);
  for (const auto& info : drag_laws()) {
    EXPECT_EQ(drag_law_from_name(info.name), info.law);
    EXPECT_EQ(drag_law_name(info.law), info.name);
    EXPECT_FALSE(info.reference.empty());
    EXPECT_FALSE(info.validity.empty());
    EXPECT_NE(drag_law_names().find(std::string(info.name)), std::string::npos);
  }
  EXPECT_FALSE(drag_law_from_name("stokes").has_value());
  EXPECT_FALSE(drag_law_from_name("BVK").has_value());
  EXPECT_EQ(drag_law_names(), "bvk, gidaspow, gidaspow_blend, wen_yu, hkl, syamlal_obrien");
}

}  // namespace
}  // namespace gridfree
