// SPDX-License-Identifier: GPL-3.0-or-later
// Cloud-in-cell weights along one axis (kernel_weights.h):
//   s = x/Δ − ½,  i₀ = ⌊s⌋,  t = s − i₀,   w(i₀) = 1 − t,  w(i₀ + 1) = t.
// The second moment about x is t(1 − t)Δ²; over a uniform sub-cell position
// it averages to Δ²/6.
#include <cmath>

#include "deposition/kernel_weights.h"

namespace gridfree {

AxisWeights trilinear_weights(double x, double h) {
  const double s = x / h - 0.5;
  const double i0 = std::floor(s);
  const double t = s - i0;
  AxisWeights w;
  w.cell = {static_cast<int>(i0), static_cast<int>(i0) + 1};
  w.weight = {1.0 - t, t};
  return w;
}

}  // namespace gridfree
