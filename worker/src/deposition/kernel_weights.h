// SPDX-License-Identifier: GPL-3.0-or-later
// One-dimensional transfer kernels (docs/PHYSICS.md §3, docs/TRANSFER.md):
// the weight a particle at coordinate x gives to each cell along one axis.
// A 3-D kernel is the product of three of these (all kernels here are
// separable), so a particle's weight in cell (i, j, k) is w_x(i) w_y(j) w_z(k).
//
//   centroid   w(i) = 1 for the cell holding x                    (variance Δ²/12 on average)
//   trilinear  cloud-in-cell: the tent of half-width Δ about x sampled at the
//              cell centres ξ_i = (i + ½)Δ: w(i) = max(0, 1 − |x − ξ_i|/Δ)
//                                                                  (variance Δ²/6 on average)
//   gaussian   the normal density N(x, σ²) integrated over each cell:
//              w(i) = ½[erf((x_{i+1} − x)/(√2σ)) − erf((x_i − x)/(√2σ))],
//              truncated at |ξ − x| ≤ mσ and renormalised so Σ w = 1 exactly
//
// The raw weights live on unbounded cell indices; fold_axis_weights() maps
// them onto the grid: wrap on a periodic axis, reflect at a zero-flux wall
// (method of images: the mass beyond the wall at 0 returns mirrored, cell
// −1−m → m, and likewise at the far wall), so Σ w = 1 on the grid.
#pragma once

#include <vector>

#include "grid/grid.h"

namespace gridfree {

// Weights on (unbounded, then folded) cell indices along one axis.
struct AxisWeights {
  std::vector<int> cell;
  std::vector<double> weight;
};

AxisWeights trilinear_weights(double x, double h);
AxisWeights gaussian_weights(double x, double h, double sigma, double truncation_sigmas);

// Maps the raw indices onto 0..n−1 (wrap or reflect), merging repeated cells
// (ascending cell order).
AxisWeights fold_axis_weights(const AxisWeights& raw, int n, bool periodic);

}  // namespace gridfree
