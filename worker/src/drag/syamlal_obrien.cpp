// SPDX-License-Identifier: GPL-3.0-or-later
// Syamlal & O'Brien (1988) drag, as in MFiX DRAG_SYAM_OBRIEN with its default
// constants c1 = 0.8, d1 = 2.65 (PHYSICS.md §4). Re_i = ρ_g |u−v| d / μ_g
// (no ε_g), A = ε_g^4.14, B = 0.8 ε_g^1.28 (ε_g ≤ 0.85) or ε_g^2.65:
//
//   V_r = ½ [A − 0.06 Re_i + √((0.06 Re_i)² + 0.12 Re_i (2B − A) + A²)]
//   D   = (3/4) μ_g ε_g (0.63 √(Re_i/V_r) + 4.8)² / (V_r d²)
//
// (the Dalla Valle C_d Re = (0.63√Re + 4.8)² at Re_i/V_r). The radicand is
// rewritten as (A − 0.06 Re_i)² + q, q = 0.24 Re_i B, visibly ≥ 0; when
// A < 0.06 Re_i the sum (A − 0.06 Re_i) + √(…) is evaluated as
// q / (√(…) − (A − 0.06 Re_i)) to avoid cancellation at large Re_i.
// At Re_i = 0, V_r = A and D = (3/4) μ_g ε_g 4.8² / (A d²): finite.
#include <cmath>

#include "drag/drag_laws_detail.h"

namespace gridfree::drag_detail {

double syamlal_obrien(const DragState& s) {
  const double re = s.rho_g * s.slip * s.d / s.mu_g;
  const double a = std::pow(s.eps_g, 4.14);
  const double b = s.eps_g <= 0.85 ? 0.8 * std::pow(s.eps_g, 1.28) : std::pow(s.eps_g, 2.65);
  const double lag = a - 0.06 * re;
  const double q = 0.24 * re * b;
  const double root = std::sqrt(lag * lag + q);
  // lag + root, written without cancellation when lag < 0 (large Re_i).
  const double v_r = lag >= 0 ? 0.5 * (lag + root) : 0.5 * q / (root - lag);
  const double c = 0.63 * std::sqrt(re / v_r) + 4.8;
  return 0.75 * s.mu_g * s.eps_g * c * c / (v_r * s.d * s.d);
}

}  // namespace gridfree::drag_detail
