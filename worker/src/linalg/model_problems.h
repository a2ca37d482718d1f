// SPDX-License-Identifier: GPL-3.0-or-later
// Model 7-point systems for the solver tests and benchmarks, built the way
// the flow solver and the filter build theirs (finite volumes on a Grid):
//
//   diffusion:  a_nb = κ_f A_f / Δ, κ_f = harmonic mean of the two cells' κ;
//               Dirichlet (φ = 0 on the boundary face) adds 2 κ_P A_f / Δ to
//               a_P; a zero-flux side adds nothing; a_P += shift·V_c
//               (the 1/Δτ term of an implicit step).
//   convection–diffusion (first-order upwind, uniform velocity u, D = Γ A/Δ,
//   F = u A):   a_W = D + max(F, 0), a_E = D + max(−F, 0) (same per axis),
//               a_P = Σ a_nb + shift·V_c — non-symmetric for u ≠ 0.
//
// bed_coefficient() is a pressure-correction-like κ field: the fictitious
// bursting-bubble geometry (PHYSICS.md §6) scaled to the domain — a dense
// bed (κ = 1/contrast) in the lowest 14 % of y with a spherical bubble
// (κ = 1) inside, and a freeboard (κ = 1) above.
#pragma once

#include <array>
#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

// Sides in the order x-low, x-high, y-low, y-high, z-low, z-high.
using DirichletSides = std::array<bool, 6>;

Stencil7 diffusion_stencil(const Grid& g, const std::vector<double>& kappa,
                           const DirichletSides& dirichlet, double shift = 0.0);

Stencil7 convection_diffusion_stencil(const Grid& g, const std::array<double, 3>& velocity,
                                      double diffusivity, const DirichletSides& dirichlet,
                                      double shift = 0.0);

std::vector<double> bed_coefficient(const Grid& g, double contrast);

}  // namespace gridfree
