// SPDX-License-Identifier: GPL-3.0-or-later
// Gidaspow drag (Ding & Gidaspow 1990) and its smooth blend (Lathouwers &
// Bellan 2000), as in MFiX DRAG_GIDASPOW / DRAG_GIDASPOW_BLEND (PHYSICS.md §4):
//
//   Ergun:  D_E = 150 ε_s μ_g / (ε_g d²) + 1.75 ρ_g |u−v| / d
//   gidaspow:        D = D_E for ε_g ≤ 0.8, D_WenYu for ε_g > 0.8 (a jump at 0.8)
//   gidaspow_blend:  ψ = arctan(262.5 (ε_g − 0.8))/π + 1/2,
//                    D = (1 − ψ) D_E + ψ D_WenYu       (262.5 = 150 · 1.75)
//
// Both pieces are finite at |u−v| = 0, so no Re guard is needed here.
#include <cmath>
#include <numbers>

#include "drag/drag_laws_detail.h"

namespace gridfree::drag_detail {

double ergun(const DragState& s) {
  const double eps_s = solids_fraction(s);
  return 150.0 * eps_s * s.mu_g / (s.eps_g * s.d * s.d) + 1.75 * s.rho_g * s.slip / s.d;
}

double gidaspow(const DragState& s) { return s.eps_g <= 0.8 ? ergun(s) : wen_yu(s); }

double gidaspow_blend(const DragState& s) {
  const double psi = std::atan(262.5 * (s.eps_g - 0.8)) / std::numbers::pi + 0.5;
  return (1.0 - psi) * ergun(s) + psi * wen_yu(s);
}

}  // namespace gridfree::drag_detail
