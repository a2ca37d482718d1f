// SPDX-License-Identifier: GPL-3.0-or-later
// One SIMPLEC sweep x ↦ G(x) with the drag field held fixed: the momentum
// predictor and the pressure correction of an outer iteration
// (docs/SOLVER.md "Algorithm: SIMPLEC", steps 2–3). run_simple iterates it
// (simple_loop.h); the Newton–Krylov prototype solves G(x) − x = 0 with it
// (newton_outer.h).
//
//   momentum  a_P u*_P = Σ a_nb u*_nb + b_P per component (BiCGSTAB, from u)
//   pressure  a_P p'_P = Σ a_nb p'_nb + b_P,  p ← p + α_p p',
//             u ← u* + d (p'_L − p'_R)         (MG-CG, from p' = 0)
//
// The inner solves stop at the relative tolerances of SimpleSettings, so the
// number of inner iterations depends on x. A directional difference
// (G(x + h v) − G(x))/h with h ~ 1e-8 |x| would then mostly measure the
// inner solves' stopping points. With `replay` set, each inner solve runs
// exactly the recorded number of iterations instead (tolerance 0), so G is
// the same sequence of arithmetic operations near x and the difference
// approximates a derivative.
#pragma once

#include <memory>

#include <array>

#include "flow/flow_state.h"
#include "flow/momentum.h"
#include "flow/simple_loop.h"

namespace gridfree {

// What the sweep keeps across calls. The work of one phase (the linear
// solvers' vectors, the pressure multigrid hierarchy, p') is allocated in
// that phase and freed at its end (docs/SOLVER.md "Memory").
struct SweepWorkspace {
  explicit SweepWorkspace(const Grid& g);
  // One system for the three momentum components in turn, whose stencil
  // then holds the pressure correction.
  MomentumSystem momentum;
  // F of the iterate entering the sweep (the momentum assembly's lagged
  // fluxes); the pressure correction then overwrites it with F of u*.
  FaceVector mass_flux;
  FaceVector d;  // SIMPLEC coefficients
  // Set once the outer loop relaxes its deferred correction
  // (SimpleSettings::relax_stalled_correction); null otherwise.
  std::unique_ptr<CorrectionRelaxation> relaxed_correction;
};

// Inner iterations of one sweep, per momentum component and for p'.
struct SweepCounts {
  std::array<int, 3> momentum{};
  int pressure = 0;
};

struct SweepReport {
  double continuity = 0;  // R_c of the iterate entering the sweep (residuals.h)
  double momentum = 0;    // R_m of the iterate entering the sweep
  int momentum_iterations = 0;
  int pressure_iterations = 0;
  bool linear_failures = false;  // an inner solve missed its tolerance (never set when replaying)
  SweepCounts counts;
};

// state ← G(state) with state.drag fixed. `seconds` (may be null) gets the
// momentum and pressure wall time added; `replay` (may be null) fixes the
// inner iteration counts.
SweepReport simplec_sweep(const FlowProblem& problem, const SimpleSettings& settings, FlowState& state,
                          SweepWorkspace& ws, PhaseSeconds* seconds, const SweepCounts* replay = nullptr);

}  // namespace gridfree
