// SPDX-License-Identifier: GPL-3.0-or-later
// Wen & Yu (1966) drag, as in MFiX DRAG_WEN_YU (PHYSICS.md §4):
//
//   D = (3/4) C_d ρ_g ε_g |u−v| ε_g^(−2.65) / d,
//   C_d = 24/Re_s (1 + 0.15 Re_s^0.687)  (Re_s ≤ 1000),  C_d = 0.44 above,
//   Re_s = ε_g ρ_g |u−v| d / μ_g.
//
// In the viscous branch C_d |u−v| = 24 μ_g (1 + 0.15 Re_s^0.687)/(ε_g ρ_g d),
// so D = 18 μ_g ε_g^(−2.65) (1 + 0.15 Re_s^0.687) / d²: no 0/0 at Re_s = 0,
// where D is the Stokes value 18 μ_g ε_g^(−2.65) / d².
#include <algorithm>
#include <cmath>

#include "drag/drag_laws_detail.h"

namespace gridfree::drag_detail {

double particle_reynolds(const DragState& s) { return s.eps_g * s.rho_g * s.slip * s.d / s.mu_g; }

double solids_fraction(const DragState& s) { return std::max(0.0, 1.0 - s.eps_g); }

double wen_yu(const DragState& s) {
  const double re = particle_reynolds(s);
  const double voidage = std::pow(s.eps_g, -2.65);
  if (re <= 1000.0) return 18.0 * s.mu_g * voidage * (1.0 + 0.15 * std::pow(re, 0.687)) / (s.d * s.d);
  return 0.75 * 0.44 * s.rho_g * s.eps_g * s.slip * voidage / s.d;
}

}  // namespace gridfree::drag_detail
