// SPDX-License-Identifier: GPL-3.0-or-later
// The one place that knows which FlowState members a checkpoint holds and
// how they are stored (flow/checkpoint.h): a change of FlowState's storage
// is an edit here only.
#pragma once

#include <string>
#include <vector>

#include "flow/flow_state.h"

namespace gridfree {

// One array of a checkpoint: its name and its values (a copy as doubles).
struct CheckpointArray {
  std::string name;
  std::vector<double> values;
};

// p, u_x, u_y, u_z, beta, beta_v_x..z (beta_v may be empty: no particles).
std::vector<CheckpointArray> checkpoint_arrays(const FlowState& state);

// The array sizes a state on this grid has (beta_v: 0 or cells). Used to
// check a checkpoint before anything is restored.
bool checkpoint_sizes_match(const Grid& grid, const std::vector<CheckpointArray>& arrays, std::string& why);

// Puts the arrays back into a state on `grid` (sizes already checked).
void restore_checkpoint_arrays(const Grid& grid, std::vector<CheckpointArray> arrays, FlowState& state);

}  // namespace gridfree
