// SPDX-License-Identifier: GPL-3.0-or-later
// Preconditioned conjugate gradients for a symmetric positive (semi)definite
// 7-point system A φ = b (Hestenes–Stiefel, with z = M⁻¹ r):
//
//   r0 = b − A φ0,  p0 = z0
//   α = (r,z)/(p,Ap),  φ += α p,  r −= α Ap,  β = (r',z')/(r,z),  p = z' + β p
//
// Singular systems (no Dirichlet anywhere: A·1 = 0): the right-hand side
// is made consistent by removing its mean, the preconditioned residual is
// projected onto zero mean, and the returned φ has zero mean.
// Convergence: ||r|| ≤ tol·||b|| (||r0|| when b = 0), checked again on the
// true residual b − A φ before reporting success. Never returns NaN: a
// breakdown (non-positive or non-finite curvature) stops with the last good φ.
#pragma once

#include <vector>

#include "linalg/preconditioner.h"
#include "linalg/stencil.h"

namespace gridfree {

// Work vectors of one solve (b only for a singular system: the consistent
// right-hand side).
struct CgWorkspace {
  std::vector<double> b, r, z, p, q, initial;
};

// Solves A φ = s.b with A from s; φ holds the initial guess on entry.
LinearSolveStats preconditioned_cg(const Stencil7& s, std::vector<double>& phi,
                                   Preconditioner& preconditioner,
                                   const LinearSolverSettings& settings, bool singular,
                                   CgWorkspace& work);

}  // namespace gridfree
