// SPDX-License-Identifier: GPL-3.0-or-later
// Fits with fixed exponents, f̂(h) = f0 + Σ_k c_k h^{e_k}, weighted least squares:
//
//     mixed          f0 + c1 h + c2 h²     (PHYSICS.md §8; EH14 eq. 6, "δ_12")
//     first order    f0 + c1 h             (EH14 eq. 4, "δ_1")
//     second order   f0 + c2 h²            (EH14 eq. 5, "δ_2")
//
// Linear in the unknowns, solved by QR (least_squares.h) with h scaled by
// h_max and f centred and scaled; coefficients are returned in the user's
// units, c_k scaling as k^{−e_k} under h → k·h. σ counts 1 + (number of
// exponents) parameters.
#pragma once

#include <vector>

#include "extrap/series.h"

namespace gridfree {

struct FixedOrderFit {
  std::vector<double> exponents;     // e_k
  double f0 = 0;
  std::vector<double> coefficients;  // c_k, same order as exponents
  double sigma = 0;                  // NaN when n ≤ number of parameters
  std::vector<double> fhat;          // f̂(h_i)
};

FixedOrderFit fit_fixed_orders(const Series& s, const std::vector<double>& w,
                               const std::vector<double>& exponents);

inline FixedOrderFit fit_mixed(const Series& s, const std::vector<double>& w) {
  return fit_fixed_orders(s, w, {1.0, 2.0});
}

}  // namespace gridfree
