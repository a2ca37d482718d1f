// SPDX-License-Identifier: GPL-3.0-or-later
// Aggregation coarsening of a 7-point system (additive correction,
// Hutchinson & Raithby 1986): the fine cells are grouped into boxes of
// 2 (or 3 at an odd end) cells along each coarsened axis, and
//
//   coarse a_nb(I→J) = Σ fine a_nb(i→j), i ∈ I, j ∈ J        (I ≠ J)
//   coarse a_P(I)    = Σ_{i∈I} (a_P,i − Σ_nb a_nb,i) + Σ_J a_nb(I→J)
//
// i.e. the Galerkin product Pᵀ A P with piecewise-constant prolongation P:
// couplings inside an aggregate move into the diagonal and each coarse row
// sum is the sum of its fine row sums (so a singular system stays singular
// and a Dirichlet part is kept). Coarse grids are again structured 7-point
// grids; periodic axes stay periodic. An axis is coarsened only where its
// coupling is strong (≥ ratio × the strongest axis): semi-coarsening for
// anisotropic cells or coefficients.
#pragma once

#include <array>
#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

struct Aggregation {
  Grid coarse;                             // the coarse grid (lengths as the fine one)
  std::array<std::vector<int>, 3> start;   // first fine index of each coarse index, + end
  std::array<std::vector<int>, 3> map;     // coarse index of each fine index
};

// Which axes to coarsen and how: none coarsened (all n = 1) gives coarse == fine.
Aggregation choose_aggregation(const Stencil7& fine, double semi_coarsening_ratio);

// Coarse coefficients (b is left at zero).
void aggregate_coefficients(const Stencil7& fine, const Aggregation& agg, Stencil7& coarse);

// coarse_I = Σ_{i∈I} fine_i.
void restrict_sum(const Grid& fine, const Aggregation& agg, const std::vector<double>& r_fine,
                  std::vector<double>& r_coarse);

// fine_i += scale · coarse_I(i).
void prolong_add(const Grid& fine, const Aggregation& agg, double scale,
                 const std::vector<double>& x_coarse, std::vector<double>& x_fine);

}  // namespace gridfree
