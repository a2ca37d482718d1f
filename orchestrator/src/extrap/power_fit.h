// SPDX-License-Identifier: GPL-3.0-or-later
// Power-law fit f̂(h) = f0 + c h^p with the order p a free parameter
// (PHYSICS.md §8; EH14 eq. 3, "δ_RE", and eqs. 8-11 for the weighted fit).
//
// For fixed p the fit is linear in (f0, c), so the problem reduces to the
// one-dimensional profile
//
//     S(p) = min_{f0,c} Σ_i w_i (f_i − f0 − c h_i^p)²,
//
// and p is its GLOBAL minimiser over p ∈ [−p_max, −p_min] ∪ [p_min, p_max]
// (default ±[0.01, 10]): a dense log-spaced scan of each side (S in closed
// form, power_law_scan_profile) locates the best bracket, golden-section search narrows it, and the root of the analytic
// derivative (envelope theorem, (f0, c) at their optimum for that p)
//
//     dS/dp = −2 Σ_i w_i r_i c h_i^p ln h_i,    r_i = f_i − f0 − c h_i^p,
//
// polishes p to machine precision. A minimum on a range boundary
// (|p| = p_min or |p| = p_max) means "p not found" (p_found = false); the fit
// at that boundary is still reported.
//
// Internally h is scaled by h_max and f is centred and scaled, so results are
// invariant under h → k·h (c then scales as k^−p) and f → a + b·f.
#pragma once

#include <vector>

#include "extrap/series.h"

namespace gridfree {

struct PowerSearch {
  double p_min = 0.01;          // smallest |p| searched
  double p_max = 10;            // largest |p| searched
  int points_per_side = 2000;   // log-spaced scan points on each sign
};

struct PowerLawFit {
  double f0 = 0, c = 0, p = 0;  // c in the user's h units
  bool p_found = false;
  double sigma = 0;             // σ with 3 parameters; NaN for n ≤ 3
  double sum_of_squares = 0;    // S(p) at the reported p
  std::vector<double> fhat;     // f̂(h_i), same order as the series
};

// s sorted (make_series); w normalised weights (fit_weights). Needs n ≥ 3.
PowerLawFit fit_power_law(const Series& s, const std::vector<double>& w,
                          const PowerSearch& search = {});

// S(p) in the user's units (for tests and plots).
double power_law_profile(const Series& s, const std::vector<double>& w, double p);

// The same S(p) as the dense scan computes it (the closed form of the
// centred two-parameter fit, no QR: 4000 of them per fit), for tests.
double power_law_scan_profile(const Series& s, const std::vector<double>& w, double p);

}  // namespace gridfree
