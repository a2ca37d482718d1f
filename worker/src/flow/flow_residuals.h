// SPDX-License-Identifier: GPL-3.0-or-later
// Residual fields of the discrete steady equations at a state (the drag
// field of the state held), for the FAS coarse-grid correction
// (two_grid_fas.h):
//
//   momentum   r_a(face) = b + Σ a_nb φ_nb − a_P φ_P  of momentum.h with
//              α_u = 1 (g cm/s², per control volume; 0 on fixed faces);
//   continuity c(cell)   = S_m V − net mass outflow   (g/s, mass_flux.h).
//
// Both are integrals over the control volume: divide by V for densities.
#pragma once

#include "flow/fields.h"
#include "flow/flow_state.h"

namespace gridfree {

FaceVector momentum_residuals(const FlowProblem& problem, const FlowState& state);
CellField continuity_residuals(const FlowProblem& problem, const FlowState& state);

}  // namespace gridfree
