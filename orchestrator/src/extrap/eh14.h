// SPDX-License-Identifier: GPL-3.0-or-later
// Eça & Hoekstra, "A procedure for the estimation of the numerical uncertainty
// of CFD calculations based on grid refinement studies", J. Comput. Phys. 262
// (2014) 104–130 [EH14], Appendix A, as implemented here:
//
//  Fits (each both unweighted, w_i = 1/n, and weighted, w_i = (1/h_i)/Σ(1/h_j),
//  EH14 eqs. 8-11; σ = sqrt(Σ n w_i r_i²/(n − k)), eqs. 12-13):
//     δ_RE  f0 + α h^p          (eq. 3; k = 3; p global over ±[0.01, 10])
//     δ_1   f0 + α h            (eq. 4; k = 2)
//     δ_2   f0 + α h²           (eq. 5; k = 2)
//     δ_12  f0 + α1 h + α2 h²   (eq. 6; k = 3)
//  Of the two variants of a fit, the one with the smaller σ is kept.
//
//  1. Observed order p from δ_RE (variant with the smaller σ).
//  2. Error estimate ε_φ(φ_i) = |f̂(h_i) − f0| of the fit chosen by p:
//       p_low ≤ p < 2  ("expected_order"): δ_RE;
//       p ≥ 2          ("high_order"):     smallest σ of δ_1, δ_2;
//       p < p_low      ("low_order") or p not found ("no_order"):
//                                          smallest σ of δ_1, δ_2, δ_12.
//  3. Data range parameter Δφ = (φ_max − φ_min)/(n − 1)           (eq. 19).
//  4. Fs = 1.25 if p_low ≤ p < p_high (default 0.5, 2.1) and σ < Δφ, else 3.
//  5. σ < Δφ:  U_φ = Fs ε_φ + σ + |φ_i − f̂(h_i)|                   (eq. 20)
//     σ ≥ Δφ:  U_φ = 3 σ/Δφ (ε_φ + σ + |φ_i − f̂(h_i)|)             (eq. 21)
//     with σ and f̂ of the fit chosen in step 2.
//
// The reported "fs" is the factor multiplying ε_φ: Fs, or 3σ/Δφ in eq. 21.
#pragma once

#include "extrap/result.h"
#include "extrap/series.h"

namespace gridfree {

// EH14 eqs. 20/21 for one grid: eps = ε_φ(φ_i), dev = |φ_i − f̂(h_i)|.
double eh14_uncertainty(double eps, double sigma, double dev, double range, double fs);

// Fills method ("eh14_<power|first|second|mixed>_<weighted|unweighted>"), f0, p,
// sigma_re, fs, sigma_over_range, fits (power, first, second, mixed), eh14
// branch and grids[].{fhat,u,rde}. Requires n ≥ 4 and non-constant f.
void eh14_extrapolate(const Series& s, const ExtrapolationOptions& opts, ExtrapolationResult& out);

}  // namespace gridfree
