// SPDX-License-Identifier: GPL-3.0-or-later
// The gas-flow problem and its unknowns on the staggered grid.
//
//   FlowProblem  what does not change during the outer iterations: grid,
//                boundaries, gas properties, convection scheme, and optional
//                manufactured sources (the code-verification hook);
//   FlowState    ε_g (frozen), p and the face velocities u (iterated), the
//                drag field β, βv̄ (updated by the coupling), and ε̄_g on the
//                faces. β̄ and (βv̄)‾ are not stored: the momentum assembly
//                averages the two cells of a face where it needs them
//                (24 B per cell less, docs/SOLVER.md "Memory").
#pragma once

#include <array>
#include <optional>

#include "coupling/drag_field.h"
#include "flow/boundary.h"
#include "flow/fields.h"
#include "grid/grid.h"
#include "schemes/limiter.h"

namespace gridfree {

struct GasProperties {
  double rho = 1e-3;                   // ρ_g, g/cm³
  double mu = 2e-4;                    // μ_g, g/(cm s)
  std::array<double, 3> gravity{};     // g, cm/s²
};

// Manufactured sources for code verification (docs/SOLVER.md, "Verification
// hook"). Empty vectors mean no source.
//   momentum[a][face]  added to the a-momentum equation, dyn/cm³ (× V);
//   mass[cell]         right-hand side of ∇·(ε_g ρ u) = S_m, g/(cm³ s).
struct FlowSources {
  std::array<std::vector<double>, 3> momentum;
  CellField mass;
};

struct FlowProblem {
  Grid grid;
  FlowBoundaries bc{};
  GasProperties gas;
  Limiter convection = Limiter::kSuperbee;
  const FlowSources* sources = nullptr;  // not owned; nullptr = none
};

struct FlowState {
  CellField eps_g;     // ε_g at cell centres (frozen)
  CellField p;         // p at cell centres, dyn/cm²
  FaceVector u;        // interstitial gas velocity on the faces, cm/s
  DragField drag;      // β at cell centres
  FaceVector eps_face;  // ε̄_g: mean of the two cells (ghosts per boundary.h)
};

// ε̄_g on every face (ghost ε_g per boundary.h).
void update_eps_faces(const FlowProblem& problem, FlowState& state);
// Sets the fixed boundary faces (walls, inflow) of state.u to their values.
void apply_fixed_faces(const FlowProblem& problem, FlowState& state);

}  // namespace gridfree
