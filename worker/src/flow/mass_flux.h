// SPDX-License-Identifier: GPL-3.0-or-later
// Face mass fluxes and the cell velocity divergence.
//
//   F_a(face) = ρ_g ε̄_g,face u_a(face) A_a          (g/s, positive along +a)
//   (∇·u)_c   = Σ_a [u_a(face c_a+1) − u_a(face c_a)] / Δ_a
//   imbalance_c = Σ_a [F_a(c_a+1) − F_a(c_a)] − S_m V   (net mass outflow)
#pragma once

#include "flow/fields.h"
#include "flow/flow_state.h"

namespace gridfree {

void compute_mass_fluxes(const FlowProblem& problem, const FlowState& state, FaceVector& flux);

CellField velocity_divergence(const Grid& grid, const FaceVector& u);

// Net mass outflow of cell c minus its mass source, g/s.
double cell_mass_imbalance(const FlowProblem& problem, const FaceVector& flux, std::size_t c);

// Σ of the mass fluxes entering through the non-periodic boundary faces and
// leaving through them (both ≥ 0), g/s.
struct BoundaryFlux {
  double in = 0;
  double out = 0;
};
BoundaryFlux boundary_mass_flux(const FlowProblem& problem, const FaceVector& flux);

}  // namespace gridfree
