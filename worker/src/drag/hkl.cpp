// SPDX-License-Identifier: GPL-3.0-or-later
// Hill, Koch & Ladd (2001) drag as extended by Benyahia, Syamlal & O'Brien
// (2006), as in MFiX DRAG_KOCH_HILL (PHYSICS.md §4). φ = ε_s, Re_h = Re_s/2:
//
//   w  = exp(−10 (0.4 − φ)/φ)
//   F0 = (1−w)[1 + 3√(φ/2) + (135/64) φ ln φ + 17.14 φ]
//            / [1 + 0.681 φ − 8.48 φ² + 8.16 φ³] + w 10φ/(1−φ)³   (0.01 < φ < 0.4)
//      = 10φ/(1−φ)³                                               (φ ≥ 0.4)
//   F1 = √(2/φ)/40 (0.01 < φ ≤ 0.1);  0.11 + 5.1e−4 exp(11.6 φ) (φ > 0.1)
//   F2 = like F0 with 17.89 φ and [1 + 0.681 φ − 11.03 φ² + 15.41 φ³]  (φ < 0.4)
//      = 10φ/(1−φ)³                                               (φ ≥ 0.4)
//   F3 = 0.9351 φ + 0.03667 (φ < 0.0953);  0.0673 + 0.212 φ + 0.0232/(1−φ)⁵
//   Re_t1 = (F2 − 1)/(3/8 − F3),  Re_t2 = [F3 + √(F3² − 4 F1 (F0 − F2))]/(2 F1)
//   F = 1 + (3/8) Re_h     if φ ≤ 0.01 and Re_h ≤ Re_t1
//     = F0 + F1 Re_h²      if φ > 0.01 and Re_h ≤ Re_t2
//     = F2 + F3 Re_h       otherwise
//   D = 18 μ_g ε_g² F / d².
//
// Continuity: the Re_h switches are exact (Re_t1, Re_t2 are where the two
// branches meet), and so is φ = 0.4 (w = 1 there). φ = 0.1 (F1) and
// φ = 0.0953 (F3) jump by < 0.1 % of F; φ = 0.01 jumps by up to ~28 % at low
// Re_h (the dilute branch is the single-sphere Oseen law 1 + 3/8 Re_h,
// while F0(0.01) ≈ 1.28): a property of the correlation, kept as MFiX has it.
// Guards: φ ln φ → 0 and w → 0 as φ → 0; the discriminant of Re_t2 is
// clamped at 0 (it is ≥ 0.013 for every 0.01 < φ < 0.99).
#include <algorithm>
#include <cmath>

#include "drag/drag_laws_detail.h"

namespace gridfree::drag_detail {
namespace {

double dense_limit(double phi) { return 10.0 * phi / std::pow(1.0 - phi, 3); }

// (1−w)·[1 + 3√(φ/2) + (135/64) φ ln φ + a φ] / [1 + 0.681 φ + b φ² + c φ³] + w·10φ/(1−φ)³.
double blended_stokes(double phi, double a, double b, double c) {
  if (phi >= 0.4) return dense_limit(phi);
  const double w = phi > 0 ? std::exp(-10.0 * (0.4 - phi) / phi) : 0.0;
  const double phi_log_phi = phi > 0 ? phi * std::log(phi) : 0.0;
  const double dilute = (1.0 + 3.0 * std::sqrt(phi / 2.0) + 135.0 / 64.0 * phi_log_phi + a * phi) /
                        (1.0 + 0.681 * phi + b * phi * phi + c * phi * phi * phi);
  return (1.0 - w) * dilute + (w > 0 ? w * dense_limit(phi) : 0.0);
}

}  // namespace

HklTerms hkl_terms(double phi) {
  HklTerms t;
  if (phi > 0.01) {
    t.f0 = blended_stokes(phi, 17.14, -8.48, 8.16);
    t.f1 = phi <= 0.1 ? std::sqrt(2.0 / phi) / 40.0 : 0.11 + 5.1e-4 * std::exp(11.6 * phi);
  }
  t.f2 = blended_stokes(phi, 17.89, -11.03, 15.41);
  t.f3 = phi < 0.0953 ? 0.9351 * phi + 0.03667 : 0.0673 + 0.212 * phi + 0.0232 / std::pow(1.0 - phi, 5);
  t.re_t1 = (t.f2 - 1.0) / (3.0 / 8.0 - t.f3);
  if (phi > 0.01) {
    const double disc = std::max(0.0, t.f3 * t.f3 - 4.0 * t.f1 * (t.f0 - t.f2));
    t.re_t2 = (t.f3 + std::sqrt(disc)) / (2.0 * t.f1);
  }
  return t;
}

double hkl_f(double phi, double re_h) {
  const HklTerms t = hkl_terms(phi);
  if (phi <= 0.01 && re_h <= t.re_t1) return 1.0 + 3.0 / 8.0 * re_h;
  if (phi > 0.01 && re_h <= t.re_t2) return t.f0 + t.f1 * re_h * re_h;
  return t.f2 + t.f3 * re_h;
}

double hkl(const DragState& s) {
  const double f = hkl_f(solids_fraction(s), 0.5 * particle_reynolds(s));
  return 18.0 * s.mu_g * s.eps_g * s.eps_g * f / (s.d * s.d);
}

}  // namespace gridfree::drag_detail
