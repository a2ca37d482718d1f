// SPDX-License-Identifier: GPL-3.0-or-later
// Newton–Krylov outer iterations: an opt-in prototype beside run_simple
// (SimpleSettings::newton_krylov_restart > 0; docs/SOLVER.md "Newton–Krylov
// prototype", docs/DESIGN.md "Outer convergence").
//
// With x = (u_x, u_y, u_z, p) stacked and G one SIMPLEC sweep with the drag
// held fixed (simplec_sweep.h), solves F(x) = G(x) − x = 0 by Jacobian-free
// Newton–GMRES (newton_krylov.h). Newton step k:
//   1. drag    β, βv̄ from x_k (held for the whole step, so F is one map);
//   2. base    F(x_k) = G(x_k) − x_k with the usual inner tolerances: its
//              residuals R_c, R_m and dp* of G(x_k) are the monitor;
//   3. test    steady when R_c < tol, R_m < tol and, from the second step on,
//              |dp*_k − dp*_{k−1}| / |dp*_k| < tol (the state is G(x_k));
//   4. Newton  GMRES(m) on J s = −F(x_k), J v by differences of G with the
//              base evaluation's inner iteration counts replayed; line search
//              on ‖F‖; fallback x_{k+1} = G(x_k) when it fails.
// Norms weight the velocity components by 1/RMS(|u|)² and p by 1/RMS(p)²,
// normalized so that ‖x_k‖ = 1 (x from step k).
// Cost unit: `iterations` counts G evaluations (one SIMPLEC sweep each),
// bounded by max_iterations; diverged/not_converged as in run_simple.
#pragma once

#include "flow/simple_loop.h"

namespace gridfree {

SimpleOutcome run_newton_krylov(const FlowProblem& problem, const SimpleSettings& settings, FlowState& state,
                                const DragUpdate& drag, const QuantityOfInterest& qoi,
                                const IterationCallback& on_iteration, const LoopControl& control = {});

}  // namespace gridfree
