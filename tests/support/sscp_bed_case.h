// SPDX-License-Identifier: GPL-3.0-or-later
// The bed of the sscp_like generator tests: 16 × 40 × 8 d of d = 0.3256 cm,
// walls in x and z, mass inflow of 219 cm/s at the bottom and a pressure
// outflow at the top (the SSCP case's particles and gas velocity, on a small
// domain).
#pragma once

#include "core/case_spec.h"

namespace gridfree::test_support {

inline CaseSpec sscp_bed_case() {
  CaseSpec c;
  c.domain_dp = {16, 40, 8};
  c.particle_diameter_cm = 0.3256;
  const BoundarySpec wall{BoundaryKind::kWall, 0, 0};
  c.boundaries[0] = {wall, wall};
  c.boundaries[2] = {wall, wall};
  c.boundaries[1] = {BoundarySpec{BoundaryKind::kMassInflow, 219, 0},
                     BoundarySpec{BoundaryKind::kPressureOutflow, 0, 0}};
  return c;
}

}  // namespace gridfree::test_support
