// SPDX-License-Identifier: GPL-3.0-or-later
// Normalized residuals of the outer iterations.
//
//   continuity  R_c = Σ_cells |net mass outflow − S_m V| / M_ref,
//               M_ref = Σ_faces |F| over every face of the grid: about the
//               summed throughput of the cells, so R_c is a cell's mean
//               relative mass imbalance and does not grow with the cell
//               count (docs/SOLVER.md, "Steady criterion");
//   momentum    R_m = Σ_components Σ_faces |b + Σ a_nb φ_nb − a_P φ_P|
//                     / Σ_components Σ_faces |a_P φ_P|,
//               evaluated at the iterate entering the outer iteration.
#pragma once

#include "flow/fields.h"

namespace gridfree {

// M_ref of the continuity residual, g/s (> 0 unless nothing flows).
double continuity_reference(const FaceVector& mass_flux);

// numerator / denominator with 0/0 = 0 and x/0 = x.
inline double normalized(double numerator, double denominator) {
  if (numerator == 0.0) return 0.0;
  return denominator > 0.0 ? numerator / denominator : numerator;
}

}  // namespace gridfree
