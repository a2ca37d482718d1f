// SPDX-License-Identifier: GPL-3.0-or-later
// What an outer loop (SIMPLEC, simple_loop.h, and the Newton–Krylov and
// two-grid FAS prototypes) concludes from one iteration's residuals: the
// divergence test and the words of its not_converged / diverged reasons.
#pragma once

#include <optional>
#include <string>

#include "flow/simple_loop.h"
#include "flow/simplec_sweep.h"

namespace gridfree {

// The monitor line of iteration `iteration` that ended in `sweep`: its
// residuals and inner iteration counts (qoi and qoi_change left to the loop).
IterationReport sweep_report(int iteration, const SweepReport& sweep);

// The quantity of interest of `state` into `r`, with its change relative to
// `previous` (1 when there is none), and `previous` updated: the monitor of
// the prototypes, which compare consecutive iterates.
void monitor_qoi_step(const QuantityOfInterest& qoi, const FlowState& state, std::optional<double>& previous,
                      IterationReport& r);

// The outcome's copy of the latest monitor line, after `iterations`.
void record_iteration(const IterationReport& r, int iterations, SimpleOutcome& out);

// A residual or change as the reasons print it (3 significant digits).
std::string residual_text(double x);

// Diverged: a non-finite residual or quantity of interest, or a residual
// above blowup × its reference (docs/SOLVER.md, "Steady criterion").
bool outer_diverged(const IterationReport& r, double blowup, double first_continuity, double first_momentum);

// A stall (numerics.stall_window) with the quantity of interest still
// moving by this fraction or more over its window is no limit cycle near a
// steady state but an iteration wandering far from one: diverged, without
// a dp* (docs/SOLVER.md "Stalled outer iterations"). Measured on
// studies/stability.json: limit cycles move dp* by at most 3.1e-4 a window,
// the wandering runs (central at Re_p 300) by 0.10 to 1, with dp* up to
// 1e21 times the converged value.
inline constexpr double kStallUnsettledQoiChange = 1e-2;

// True when a stall ends an iteration whose quantity of interest has not
// settled: see kStallUnsettledQoiChange.
bool stall_is_divergence(const IterationReport& r);

// "continuity residual …, momentum residual …"
std::string residuals_text(double continuity, double momentum);

// "not converged after <count>: continuity residual …, momentum residual …,
// relative change of the quantity of interest … (tolerance …)"
std::string not_converged_reason(const std::string& count, const SimpleOutcome& out, double tolerance);

// The numbers of the last iteration on which the steady criterion was checked.
struct SteadyCheck {
  int iteration = 0;
  double continuity = 0, momentum = 0;
  std::optional<double> qoi_change;  // empty without a quantity of interest
};

// What a not_converged reason adds when the steady criterion is checked only
// on drag-update iterations (drag_interval > 1), since the residuals it
// quotes are the last iteration's, not the last check's: "; the steady
// criterion is checked on drag-update iterations (every 4th); the last check,
// at iteration 29, failed on the continuity residual 2.1e-05 ≥ 1e-05". Empty
// when every iteration is checked.
std::string steady_check_note(const std::optional<SteadyCheck>& last, int drag_interval, int min_iterations,
                              double tolerance);

}  // namespace gridfree
