// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary conditions of the gas flow as ghost values (PHYSICS.md §2).
//
// Each non-periodic domain side is one of
//   wall              no-slip: normal face velocity 0; ghost tangential
//                     velocity = −(fluid value), so the wall value is 0;
//                     ghost ε_g = ε_g of the adjacent cell;
//   mass_inflow       gas only: ghost ε_g = 1; the boundary face velocity is
//                     fixed, u_face = U0 / ε̄_face with ε̄_face = ½(1 + ε_g,P),
//                     so the inlet mass flux ρ ε̄ u = ρ U0 per unit area;
//                     ghost tangential velocity 0; d = 0 on the face;
//   pressure_outflow  p fixed at the ghost-cell centre (half a cell outside);
//                     zero-gradient velocity and ε_g; no viscous flux.
// Periodic axes have no ghosts: every index wraps.
#pragma once

#include <array>

#include "grid/grid.h"
#include "core/case_spec.h"

namespace gridfree {

// boundaries[axis][side], side 0 = low, 1 = high (as in CaseSpec).
using FlowBoundaries = std::array<std::array<BoundarySpec, 2>, 3>;

// How the velocity normal to a face is determined.
enum class FaceRole {
  kInterior,  // an unknown of the momentum equation (includes periodic faces)
  kFixed,     // wall (0) or mass inflow (U0/ε̄): known, d = 0
  kOutflow,   // pressure-outflow boundary face: unknown, p' = 0 in the ghost
};

// Role of face f (0..n_a) normal to `axis`.
FaceRole face_role(const Grid& grid, const FlowBoundaries& bc, int axis, int f);

// Side (0 low, 1 high) of a boundary face f normal to `axis`.
inline int face_side(int f) { return f == 0 ? 0 : 1; }

// Gas fraction in the ghost cell beyond `side` of `axis`, given the adjacent
// fluid cell's value: 1 at a mass inflow, zero-gradient otherwise.
double ghost_eps_g(const BoundarySpec& side_bc, double eps_g_inside);

// Prescribed normal velocity of a fixed boundary face, in +axis direction:
// wall 0; mass inflow +U0/ε̄ on the low side, −U0/ε̄ on the high side.
double fixed_face_velocity(const BoundarySpec& side_bc, int side, double eps_face);

// A ghost value of a velocity component tangential to the boundary:
//   φ_ghost = scale · φ_P + value, with viscous coupling `diffusion` (0 or 1)
// times μ A / Δ across the boundary.
struct TangentialGhost {
  double scale = 0;
  double value = 0;
  double diffusion = 1;
};
TangentialGhost tangential_ghost(const BoundarySpec& side_bc);

// True when some side is a pressure outflow (the pressure level is fixed).
bool has_pressure_outlet(const FlowBoundaries& bc);

}  // namespace gridfree
