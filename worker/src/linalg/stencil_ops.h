// SPDX-License-Identifier: GPL-3.0-or-later
// Basic operations on a 7-point finite-volume system (stencil.h):
//
//   (A φ)_P = a_P φ_P − Σ_nb a_nb φ_nb          (matrix–vector product)
//   r_P     = b_P − (A φ)_P                       (residual, stencil_residual)
//
// and the checks the solvers rely on: boundary coefficients must be zero
// across non-periodic boundaries, and a system with no Dirichlet anywhere
// (Σ_nb a_nb = a_P in every row) is singular with the constants as its null
// space. Loops run over rows of x (fixed j, k) with OpenMP; every output
// value is computed by exactly one thread, so results do not depend on the
// thread count.
#pragma once

#include <cstddef>
#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

// Start indices of the rows holding the S/N/B/T neighbours of row (j, k).
// Across a non-periodic boundary the row itself is returned (the coefficient
// there is zero, so the value read does not matter).
struct RowNeighbours {
  std::size_t self, south, north, bottom, top;
};
RowNeighbours row_neighbours(const Grid& g, int j, int k);

// y = A φ.
void stencil_apply(const Stencil7& s, const std::vector<double>& phi, std::vector<double>& y);

// True when no row has a Dirichlet part: |a_P − Σ_nb a_nb| ≤ tol·a_P in every
// row (tol absorbs round-off from how the coefficients were summed).
bool stencil_is_singular(const Stencil7& s, double relative_tolerance = 1e-10);

// Throws std::invalid_argument if an array has the wrong size or a
// coefficient across a non-periodic boundary is non-zero.
void check_stencil(const Stencil7& s);

// Largest |a_nb(c→d) − a_nb(d→c)| relative to a_P over all couplings.
double stencil_asymmetry(const Stencil7& s);

}  // namespace gridfree
