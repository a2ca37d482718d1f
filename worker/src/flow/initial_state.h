// SPDX-License-Identifier: GPL-3.0-or-later
// Iteration-0 state (warm start) of a frozen-bed solve.
//
//   ε_g = 1 − ε_s;
//   u_y = U0 / ε̄_g on the y faces (plug flow carrying the inlet mass flux),
//   u_x = u_z = 0;
//   p from the 1-D momentum balance of each x–z row with the drag of that
//   plug flow:  dp/dy = ρ_g g_y − ⟨β U0 / ε_g²⟩_row, integrated downwards
//   from the outlet ghost (p = p_out half a cell above the top row).
#pragma once

#include "flow/flow_state.h"
#include "flow/simple_loop.h"

namespace gridfree {

// Superficial inflow velocity U0 through y_low (or y_high), 0 when none.
double inflow_velocity(const FlowBoundaries& bc);

// Sets eps_g, u, p of `state` as above; `drag` (may be empty) gives β for
// the pressure estimate. With cold = true: u = 0 and p = 0 instead (only the
// fixed boundary faces set), to test that the iterations find the solution.
void warm_start(const FlowProblem& problem, const std::vector<double>& eps_s,
                const DragUpdate& drag, FlowState& state, bool cold = false);

}  // namespace gridfree
