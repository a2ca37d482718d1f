// SPDX-License-Identifier: GPL-3.0-or-later
// Folding raw kernel weights onto the grid (kernel_weights.h).
//   periodic:  i → i mod n
//   wall:      i → r = i mod 2n;  r ≥ n ? 2n − 1 − r : r   (images at both walls)
// Weight is only moved, never created or dropped: Σ w is unchanged.
#include <map>

#include "deposition/kernel_weights.h"

namespace gridfree {

AxisWeights fold_axis_weights(const AxisWeights& raw, int n, bool periodic) {
  std::map<int, double> merged;
  for (std::size_t m = 0; m < raw.cell.size(); ++m) {
    int i = raw.cell[m];
    if (periodic) {
      i %= n;
      if (i < 0) i += n;
    } else {
      int r = i % (2 * n);
      if (r < 0) r += 2 * n;
      i = r >= n ? 2 * n - 1 - r : r;
    }
    merged[i] += raw.weight[m];
  }
  AxisWeights out;
  for (const auto& [cell, w] : merged) {
    out.cell.push_back(cell);
    out.weight.push_back(w);
  }
  return out;
}

}  // namespace gridfree
