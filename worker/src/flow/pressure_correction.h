// SPDX-License-Identifier: GPL-3.0-or-later
// SIMPLEC pressure correction.
//
// With u_f = u*_f + d_f (p'_L − p'_R) on every face (d = 0 on fixed faces),
// mass conservation of cell P,  Σ_faces ±ρ ε̄_f A_f u_f = S_m V,  becomes
//
//   a_P p'_P = Σ_nb a_nb p'_nb + b_P,
//   a_nb = ρ ε̄_f A_f d_f,   a_P = Σ a_nb (+ ρ ε̄ A d of an outflow face, whose
//                            ghost has p' = 0),
//   b_P  = S_m V − Σ_faces (net outflow of F* = ρ ε̄ u* A).
//
// The system is symmetric (solve_symmetric). Then p ← p + α_p p' and every
// face velocity u ← u* + d (p'_L − p'_R). Without a pressure outlet the
// level of p is fixed by setting its mean to zero.
#pragma once

#include "core/solve_stats.h"
#include "flow/fields.h"
#include "flow/flow_state.h"
#include "linalg/stencil.h"
#include "linalg/symmetric_solver.h"

namespace gridfree {

struct PressureCorrectionResult {
  double imbalance = 0;  // Σ_cells |b_P| before the correction (g/s)
  LinearSolveStats solve;
};

// `eq` and `p_prime` are work space on the cell grid; `flux` is work space
// on the faces (left holding F of u*, before the correction).
PressureCorrectionResult correct_pressure(const FlowProblem& problem, FlowState& state,
                                          const FaceVector& d, double relax_p,
                                          const LinearSolverSettings& settings, Stencil7& eq,
                                          SymmetricSolver& solver, std::vector<double>& p_prime,
                                          FaceVector& flux);

}  // namespace gridfree
