// SPDX-License-Identifier: GPL-3.0-or-later
// The linear system of one backward-Euler step of the diffusion filter
// (PHYSICS.md §3.2), and the correction that makes it conserve exactly.
//
// One step of Δτ:  (I − Δτ Σ_i ν_i δ²_i) α^{n+1} = α^n, δ²_i the 3-point
// second difference along axis i. In the 7-point form of linalg/stencil.h:
//
//   a_nb = ν_i Δτ / Δ_i²  for each neighbour across an interior or periodic
//          face of an active axis, 0 across a non-periodic boundary (zero flux),
//   a_P  = 1 + Σ a_nb,    b = α^n.
//
// Every row and every column of A sums to 1 (A is symmetric and each face
// coefficient enters one diagonal and one off-diagonal of the same column),
// so 1ᵀ A x = 1ᵀ x: Σ α^{n+1} = Σ α^n exactly for the exact solution, and
// A 1 = 1. An axis is active when ν_i > 0 and it has more than one cell.
// The matrix is the same for every step; only b changes.
#pragma once

#include <array>
#include <vector>

#include "grid/grid.h"
#include "linalg/stencil.h"

namespace gridfree::filter_detail {

// Assembles the step matrix (b left zero).
Stencil7 assemble_filter_step(const Grid& grid, const std::array<double, 3>& nu, double dtau);

// An iterative solve leaves Σ x − Σ b = −Σ r (r = b − A x, since 1ᵀA = 1ᵀ).
// Because A 1 = 1, x += mean(r) is the exact correction of the residual's
// constant part: afterwards Σ x = Σ b to round-off, whatever the tolerance.
// Returns ||b − A x|| / ||b|| after the correction (0 when b = 0).
double remove_mean_residual(const Stencil7& s, std::vector<double>& x);

}  // namespace gridfree::filter_detail
