// SPDX-License-Identifier: GPL-3.0-or-later
// Beetstra, van der Hoef & Kuipers (2007) drag, monodisperse, as in MFiX
// DRAG_BVK (PHYSICS.md §4). With φ = ε_s, Re = Re_s = ε_g ρ_g |u−v| d / μ_g:
//
//   F = 10φ/ε_g² + ε_g² (1 + 1.5√φ)
//       + [0.413 Re / (24 ε_g²)] · [1/ε_g + 3 ε_g φ + 8.4 Re^(−0.343)]
//                                / [1 + 10^(3φ) Re^(−(1+4φ)/2)],
//   D = 18 μ_g ε_g F / d²   (so β = 18 μ_g ε_g ε_s F / d²).
//
// Re → 0: the inertial term is written with a = (1+4φ)/2 and x = Re^a as
//   [0.413/(24 ε_g²)] · [Re (1/ε_g + 3 ε_g φ) + 8.4 Re^0.657] · x/(x + 10^(3φ)),
// (numerator and denominator multiplied by Re^a), every power positive, so
// it is 0 at Re = 0 and F is the Stokes-flow value 10φ/ε_g² + ε_g²(1 + 1.5√φ).
#include <cmath>

#include "drag/drag_laws_detail.h"

namespace gridfree::drag_detail {

double bvk_f(double phi, double re) {
  const double eps_g = 1.0 - phi;
  const double eps_g2 = eps_g * eps_g;
  const double viscous = 10.0 * phi / eps_g2 + eps_g2 * (1.0 + 1.5 * std::sqrt(phi));
  const double x = std::pow(re, 0.5 + 2.0 * phi);
  const double k = std::pow(10.0, 3.0 * phi);
  const double switch_on = x > k ? 1.0 / (1.0 + k / x) : x / (x + k);  // x/(x+k), overflow-safe
  const double bracket = re * (1.0 / eps_g + 3.0 * eps_g * phi) + 8.4 * std::pow(re, 0.657);
  return viscous + 0.413 / (24.0 * eps_g2) * bracket * switch_on;
}

double bvk(const DragState& s) {
  const double phi = solids_fraction(s);
  const double f = bvk_f(phi, particle_reynolds(s));
  return 18.0 * s.mu_g * s.eps_g * f / (s.d * s.d);
}

}  // namespace gridfree::drag_detail
