// Normalized residuals of the outer iterations.
//
//   continuity  R_c = Σ_cells |net mass outflow − S_m V| / M_ref,
//               M_ref = Σ inflow mass flux through the boundaries (ρ U0 A);
//               with no inflow, the mean |F| through one cross-section of the
//               most-crossed axis, Σ_faces |F_a| / n_a;
//   momentum    R_m = Σ_components Σ_faces |b + Σ a_nb φ_nb − a_P φ_P|
//                     / Σ_components Σ_faces |a_P φ_P|,
//               evaluated at the iterate entering the outer iteration.
#pragma once

#include "flow/fields.h"
#include "flow/flow_state.h"

namespace gridfree {

// M_ref of the continuity residual, g/s (> 0 unless nothing flows).
double continuity_reference(const FlowProblem& problem, const FaceVector& mass_flux);

// numerator / denominator with 0/0 = 0 and x/0 = x.
inline double normalized(double numerator, double denominator) {
  if (numerator == 0.0) return 0.0;
  return denominator > 0.0 ? numerator / denominator : numerator;
}

}  // namespace gridfree
