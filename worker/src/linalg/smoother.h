// SPDX-License-Identifier: GPL-3.0-or-later
// Red-black Gauss–Seidel smoothing of A x = rhs on a 7-point stencil:
//
//   x_P ← (rhs_P + Σ_nb a_nb x_nb) / a_P     for every cell of one colour,
//
// colour = (i + j + k) mod 2. Cells of one colour only couple to the other
// colour, except across a periodic axis with an odd cell count; there the
// colour is updated Jacobi-style (all new values from the old ones, through
// a scratch array), so each colour step stays a fixed symmetric operator
// P_c D_c⁻¹ P_cᵀ and the result does not depend on the thread count.
//
// A forward sweep (red then black) followed by a backward sweep (black then
// red) is the symmetric smoother that keeps a multigrid V-cycle symmetric,
// as conjugate gradients requires. Rows with a_P = 0 are left unchanged.
#pragma once

#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

enum class SweepOrder { kForward, kBackward };

// One colour step (colour 0 = (i+j+k) even).
void gauss_seidel_colour(const Stencil7& a, const std::vector<double>& rhs, std::vector<double>& x,
                         int colour, std::vector<double>& scratch);

// Red then black (kForward) or black then red (kBackward).
void gauss_seidel_sweep(const Stencil7& a, const std::vector<double>& rhs, std::vector<double>& x,
                        SweepOrder order, std::vector<double>& scratch);

}  // namespace gridfree
