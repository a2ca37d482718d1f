// SPDX-License-Identifier: GPL-3.0-or-later
// BiCGSTAB (van der Vorst 1992) with right preconditioning for general
// (non-symmetric) 7-point systems such as the momentum equations:
//
//   ρ = (r̂, r),  β = (ρ/ρ_old)(α/ω),  p = r + β (p − ω v)
//   p̂ = M⁻¹p,  v = A p̂,  α = ρ / (r̂, v),  s = r − α v
//   ŝ = M⁻¹s,  t = A ŝ,  ω = (t, s)/(t, t)
//   φ += α p̂ + ω ŝ,  r = s − ω t
//
// Breakdowns ((r̂, r) ≈ 0 or (r̂, v) ≈ 0 relative to the norms, ω = 0) restart
// with r̂ = r from the current iterate (a few times at most); any
// non-finite scalar stops the solve with the last finite φ, so φ never
// becomes NaN. Convergence: ||r|| ≤ tol·||b|| (||r0|| when b = 0), confirmed
// on the true residual.
#pragma once

#include <vector>

#include "linalg/preconditioner.h"
#include "linalg/stencil.h"

namespace gridfree {

enum class GeneralPreconditioner { kJacobi, kGaussSeidel };

struct GeneralSolverOptions {
  GeneralPreconditioner preconditioner = GeneralPreconditioner::kGaussSeidel;
  int max_restarts = 5;  // after breakdowns
};

// solve_general (stencil.h) with explicit options.
LinearSolveStats solve_general(const Stencil7& s, std::vector<double>& phi,
                               const LinearSolverSettings& settings,
                               const GeneralSolverOptions& options);

// The iteration itself, with any preconditioner.
LinearSolveStats bicgstab(const Stencil7& s, std::vector<double>& phi,
                          Preconditioner& preconditioner, const LinearSolverSettings& settings,
                          int max_restarts);

}  // namespace gridfree
