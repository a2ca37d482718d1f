// SPDX-License-Identifier: GPL-3.0-or-later
// Ghost-value rules of PHYSICS.md §2 (see boundary.h).
#include "flow/boundary.h"

namespace gridfree {

FaceRole face_role(const Grid& grid, const FlowBoundaries& bc, int axis, int f) {
  if (grid.periodic[axis] || (f > 0 && f < grid.n[axis])) return FaceRole::kInterior;
  const BoundarySpec& side = bc[axis][face_side(f)];
  switch (side.kind) {
    case BoundaryKind::kPressureOutflow: return FaceRole::kOutflow;
    case BoundaryKind::kPeriodic: return FaceRole::kInterior;  // not reached: axis periodic
    case BoundaryKind::kWall:
    case BoundaryKind::kMassInflow: return FaceRole::kFixed;
  }
  return FaceRole::kFixed;
}

double ghost_eps_g(const BoundarySpec& side_bc, double eps_g_inside) {
  return side_bc.kind == BoundaryKind::kMassInflow ? 1.0 : eps_g_inside;
}

double fixed_face_velocity(const BoundarySpec& side_bc, int side, double eps_face) {
  if (side_bc.kind != BoundaryKind::kMassInflow) return 0.0;
  const double u = side_bc.superficial_velocity_cm_s / eps_face;
  return side == 0 ? u : -u;
}

TangentialGhost tangential_ghost(const BoundarySpec& side_bc) {
  switch (side_bc.kind) {
    case BoundaryKind::kWall: return {-1.0, 0.0, 1.0};
    case BoundaryKind::kMassInflow: return {0.0, 0.0, 1.0};
    case BoundaryKind::kPressureOutflow: return {1.0, 0.0, 0.0};
    case BoundaryKind::kPeriodic: break;
  }
  return {1.0, 0.0, 0.0};
}

bool has_pressure_outlet(const FlowBoundaries& bc) {
  for (const auto& axis : bc)
    for (const auto& side : axis)
      if (side.kind == BoundaryKind::kPressureOutflow) return true;
  return false;
}

}  // namespace gridfree
