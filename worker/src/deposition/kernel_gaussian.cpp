// SPDX-License-Identifier: GPL-3.0-or-later
// Exact cell integrals of a truncated normal density along one axis
// (kernel_weights.h):
//   w(i) = ½[erf((b_i − x)/(√2σ)) − erf((a_i − x)/(√2σ))] / Z,
//   [a_i, b_i] = [iΔ, (i+1)Δ] ∩ [x − mσ, x + mσ],  Z = erf(m/√2) (so Σ w = 1).
// Z is the sum of the un-normalised weights themselves, so the sum is 1 to
// round-off whatever m.
#include <algorithm>
#include <cmath>

#include "deposition/kernel_weights.h"

namespace gridfree {

AxisWeights gaussian_weights(double x, double h, double sigma, double truncation_sigmas) {
  const double lo = x - truncation_sigmas * sigma, hi = x + truncation_sigmas * sigma;
  const int first = static_cast<int>(std::floor(lo / h));
  const int last = static_cast<int>(std::floor(hi / h));
  const double scale = 1.0 / (std::sqrt(2.0) * sigma);
  AxisWeights w;
  double total = 0;
  for (int i = first; i <= last; ++i) {
    const double a = std::max(lo, i * h), b = std::min(hi, (i + 1) * h);
    if (!(b > a)) continue;
    const double v = 0.5 * (std::erf((b - x) * scale) - std::erf((a - x) * scale));
    w.cell.push_back(i);
    w.weight.push_back(v);
    total += v;
  }
  for (double& v : w.weight) v /= total;
  return w;
}

}  // namespace gridfree
