// SPDX-License-Identifier: GPL-3.0-or-later
// Two-grid FAS (full approximation scheme) with SIMPLEC as the smoother: an
// opt-in prototype (SimpleSettings::fas_smoothing_sweeps > 0; docs/SOLVER.md
// "FAS prototype", docs/DESIGN.md "Outer convergence").
//
// Level h is the job's grid, level H the nested start's coarser grid with
// its own ε_s and drag from the same particles. One cycle:
//   1. drag     β_h from u_h;
//   2. smooth   ν SIMPLEC sweeps on h (simplec_sweep.h); the last one's
//               residuals and dp* are the monitor (steady as in
//               newton_outer.h, with the dp* change between cycles);
//   3. restrict û_H = I u_h, p̂_H = I p_h (trilinear, prolong.h) and the
//               residual densities r_h/V_h, c_h/V_h (flow_residuals.h);
//   4. τ        coarse sources S = I(r_h/V_h) − r_H(û_H)/V_H (momentum) and
//               I(c_h/V_h) − c_H(û_H)/V_H (mass), so that û_H solves the
//               coarse problem exactly when u_h solves the fine one;
//   5. coarse   `coarse_sweeps` SIMPLEC iterations of the coarse problem
//               with S (run_simple, FlowProblem::sources) from (û_H, p̂_H);
//   6. correct  u_h += I(u_H − û_H), p_h += I(p_H − p̂_H), fixed faces reset.
// Restriction by trilinear interpolation, not by volume averaging: the
// grids are not nested when a cell count is odd (15 → 8).
// `iterations` counts fine sweeps; coarse sweeps are reported separately.
#pragma once

#include "flow/simple_loop.h"

namespace gridfree {

struct FasLevel {
  const FlowProblem* problem = nullptr;
  FlowState* state = nullptr;  // ε_g, p, u, drag
  DragUpdate drag;
};

struct FasOutcome {
  SimpleOutcome outcome;  // iterations = fine sweeps
  int cycles = 0;
  int coarse_sweeps = 0;
};

FasOutcome run_two_grid_fas(const FasLevel& fine, FasLevel& coarse, const SimpleSettings& settings,
                            const QuantityOfInterest& qoi, const IterationCallback& on_iteration);

}  // namespace gridfree
