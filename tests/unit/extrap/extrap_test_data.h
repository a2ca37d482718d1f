// SPDX-License-Identifier: GPL-3.0-or-later
// Synthetic series shared by the extrap/ unit tests.
#pragma once

#include <cmath>
#include <vector>

#include "extrap/extrapolation.h"

namespace gridfree::test {

// n cell sizes geometrically spaced from h_fine to h_coarse (ascending).
inline std::vector<double> geometric_h(int n, double h_fine, double h_coarse) {
  std::vector<double> h;
  for (int i = 0; i < n; ++i) h.push_back(h_fine * std::pow(h_coarse / h_fine, double(i) / (n - 1)));
  return h;
}

// A typical refinement sequence (8 grids, Δ* 0.16 … 3.3, ratio ≈ 1.54).
inline std::vector<double> default_h() { return geometric_h(8, 0.16, 3.3); }

inline std::vector<double> power_law(const std::vector<double>& h, double f0, double c, double p) {
  std::vector<double> f;
  for (double hi : h) f.push_back(f0 + c * std::pow(hi, p));
  return f;
}

inline std::vector<double> mixed_law(const std::vector<double>& h, double f0, double c1, double c2) {
  std::vector<double> f;
  for (double hi : h) f.push_back(f0 + c1 * hi + c2 * hi * hi);
  return f;
}

// The paper-like oscillatory series: 18 grids, Δ* 0.16 … 3.3, f around
// 1158.8 with a grid-to-grid oscillation that shrinks linearly with h:
//     f(h) = 1158.8 + 0.4 h sin(7/h).
inline std::vector<double> oscillatory_h() { return geometric_h(18, 0.16, 3.3); }
inline std::vector<double> oscillatory_f(const std::vector<double>& h) {
  std::vector<double> f;
  for (double hi : h) f.push_back(1158.8 + 0.4 * hi * std::sin(7.0 / hi));
  return f;
}

// The paper's procedure as published (--method fm). The default, capped,
// differs from it only when the observed order exceeds p_high.
// A method's own formulas, before the bias checks widen U (bias_checks.h).
inline ExtrapolationOptions formula_of(ExtrapolationMethod method, ExtrapolationOptions opts = {}) {
  opts.method = method;
  opts.leave_one_out = false;
  return opts;
}

inline ExtrapolationResult extrapolate_fm(const std::vector<double>& h, const std::vector<double>& f,
                                          ExtrapolationOptions opts = {}) {
  return extrapolate(h, f, formula_of(ExtrapolationMethod::kFm, opts));
}

}  // namespace gridfree::test
