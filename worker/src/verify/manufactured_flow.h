// SPDX-License-Identifier: GPL-3.0-or-later
// Manufactured solution of the steady Model A gas equations (PHYSICS.md §1)
// with a frozen, prescribed gas fraction and drag field in a periodic box:
//
//   ∇·(ε ρ u u) = −ε ∇p + ∇·τ − β u + S_u,    ∇·(ε ρ u) = S_m,
//   τ = μ(∇u + ∇uᵀ) − ⅔ μ (∇·u) I,
//
// on [0,1]² × [0,Δ] (x, y periodic, one periodic cell in z, w = 0) with
//   ε(x,y) = 0.6 + 0.15 sin(kx) sin(ky)
//   u(x,y) = 1 + 0.5 sin(kx) cos(ky),   v(x,y) = 0.8 + 0.4 cos(kx) sin(2ky)
//   p(x,y) = 0.5 cos(kx) sin(ky),       β(x,y) = 2 (1 + 0.5 cos(kx) cos(ky))
// k = 2π, ρ = 1, μ = 0.01 (Re = ρUL/μ = 100: convection, pressure, viscous
// and drag terms are all of order one). S_u and S_m are the exact
// continuous residuals of this field, evaluated at face and cell centres.
// The solver's discrete solution must approach it at the scheme's order.
#pragma once

#include <vector>

#include "schemes/limiter.h"
#include "verify/order_study.h"

namespace gridfree {

// The study's description (equation, scheme, norm, expected order), no grids yet.
OrderStudy manufactured_flow_study(Limiter scheme);
// One grid: the L1 velocity error, or why the solver did not converge.
GridOutcome manufactured_flow_outcome(Limiter scheme, int n);

// Solves the manufactured problem on n×n×1 grids for `scheme` and measures
// the L1 error of the face velocities (mean |u_h − u| over all x- and y-faces).
OrderStudy manufactured_flow_order(Limiter scheme, const std::vector<int>& grids);

// The L1 velocity error on one n×n×1 grid; `iterations` receives the SIMPLE
// iterations used. Throws std::runtime_error when the solver does not converge.
double manufactured_flow_error(Limiter scheme, int n, int* iterations = nullptr);

}  // namespace gridfree
