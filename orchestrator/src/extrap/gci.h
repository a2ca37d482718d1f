// SPDX-License-Identifier: GPL-3.0-or-later
// Three-grid Richardson extrapolation and Grid Convergence Index, Celik et al.,
// ASME J. Fluids Eng. 130 (2008) 078001 [C08], for grids h1 < h2 < h3
// (1 = finest):
//
//     r21 = h2/h1, r32 = h3/h2, ε21 = φ2 − φ1, ε32 = φ3 − φ2, s = sign(ε32/ε21)
//     p = |ln|ε32/ε21| + q(p)| / ln r21,  q(p) = ln((r21^p − s)/(r32^p − s))   [C08 eqs. 5a-c]
//         solved by fixed-point iteration from q = 0 (exact when r21 = r32)
//     φ_ext21 = (r21^p φ1 − φ2)/(r21^p − 1)                                   [C08 eq. 6a]
//     e_a21 = |(φ1 − φ2)/φ1|,  e_ext21 = |(φ_ext21 − φ1)/φ_ext21|             [C08 eqs. 7a, 7b]
//     GCI_fine21 = 1.25 e_a21/(r21^p − 1)    (relative, as C08 eq. 7c defines it)
//
// Convergence type, judged against r^p with the two ratios as they are
// (r21 ≠ r32 after a failed grid is dropped): one term k h^p with p > 0 gives
//
//     ε32/ε21 = g(p) = r21^p (r32^p − 1)/(r21^p − 1),
//
// and g increases with p from g(0+) = ln r32/ln r21 (d ln g/dp =
// ln r32/(1 − r32^−p) − ln r21/(r21^p − 1), and the first term exceeds 1/p,
// the second is below it). So the signed form of
// C08 eq. 5 (s = +1) has a root p > 0 exactly when ε32/ε21 > ln r32/ln r21:
// "monotone"; ε32/ε21 < 0 (C08: s = −1): "oscillatory"; else "divergent"
// (no positive order fits; with r21 = r32 this is R = ε21/ε32 ≥ 1, the
// equal-ratio rule). R is kept for the table. Status "ok", or why the
// numbers are missing:
// "zero_difference" (ε21 = 0 or ε32 = 0), "no_convergence_of_order_iteration"
// (the fixed-point iteration failed to settle in kMaxIterations or left the
// domain of q), "zero_order" (p = 0: r^p − 1 = 0), "order_overflow" (r21^p
// not finite), "zero_fine_value" (φ1 = 0: relative measures undefined).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "extrap/series.h"

namespace gridfree {

struct GciTriplet {
  std::array<double, 3> h{}, f{};        // finest first
  double r21 = 0, r32 = 0;
  std::optional<double> ratio;           // R = ε21/ε32
  std::optional<std::string> convergence;  // monotone | oscillatory | divergent
  std::optional<double> p, f_ext, e_a21, e_ext21;
  std::optional<double> gci_fine;        // relative (C08 eq. 7c)
  std::optional<double> gci_fine_abs;    // 1.25 |φ1 − φ2|/(r21^p − 1), f's units
  int iterations = 0;                    // fixed-point iterations used
  std::string status = "ok";
};

inline constexpr int kGciMaxIterations = 10000;

// monotone | oscillatory | divergent as above; nothing when ε21 or ε32 is 0.
std::optional<std::string> convergence_type(double r21, double r32, double e21, double e32);

// One triplet; h strictly increasing.
GciTriplet gci_triplet(const std::array<double, 3>& h, const std::array<double, 3>& f);

// Every consecutive triplet of a sorted series, finest first (n − 2 entries).
std::vector<GciTriplet> gci_triplets(const Series& s);

}  // namespace gridfree
