// What an outer loop (SIMPLEC, simple_loop.h, and the Newton–Krylov and
// two-grid FAS prototypes) concludes from one iteration's residuals: the
// divergence test and the words of its not_converged / diverged reasons.
#pragma once

#include <string>

#include "flow/simple_loop.h"

namespace gridfree {

// A residual or change as the reasons print it (3 significant digits).
std::string residual_text(double x);

// Diverged: a non-finite residual or quantity of interest, or a residual
// above blowup × its reference (docs/SOLVER.md, "Steady criterion").
bool outer_diverged(const IterationReport& r, double blowup, double first_continuity, double first_momentum);

// "continuity residual …, momentum residual …"
std::string residuals_text(double continuity, double momentum);

// "not converged after <count>: continuity residual …, momentum residual …,
// relative change of the quantity of interest … (tolerance …)"
std::string not_converged_reason(const std::string& count, const SimpleOutcome& out, double tolerance);

}  // namespace gridfree
