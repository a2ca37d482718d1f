// SPDX-License-Identifier: GPL-3.0-or-later
// Nested iteration: the initial guess of a fine grid from the solution on a
// coarser grid of the same domain (docs/SOLVER.md, "Nested start").
//
// Every value lives on a lattice: cell centres x_i = (i + ½) Δ for p; for
// the velocity component a, its faces x_i = i Δ_a along a and cell centres
// across. The fine value at point x is the trilinear interpolant of the
// coarse lattice,
//
//   φ_f(x) = Σ_corners Π_axes w_axis · φ_c(corner),
//
// wrapped on periodic axes and held constant beyond the first and last
// coarse lattice point on the others. Fixed boundary faces are reset by the
// outer loop (apply_fixed_faces).
#pragma once

#include "flow/fields.h"
#include "grid/grid.h"

namespace gridfree {

// p on the fine cells from p on the coarse cells.
CellField prolong_cells(const Grid& coarse, const CellField& values, const Grid& fine);

// Face velocities on the fine faces from those on the coarse faces.
FaceVector prolong_faces(const Grid& coarse, const FaceVector& values, const Grid& fine);

}  // namespace gridfree
