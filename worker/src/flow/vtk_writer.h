// SPDX-License-Identifier: GPL-3.0-or-later
// Final fields as a legacy VTK file (STRUCTURED_POINTS, binary, CELL_DATA),
// which ParaView opens: eps_s, eps_g, p, beta and the gas velocity at cell
// centres (mean of the two faces per component). Coordinates in cm.
#pragma once

#include <filesystem>
#include <vector>

#include "flow/flow_state.h"

namespace gridfree {

// Writes `file` (creating its folder); throws std::runtime_error on I/O failure.
void write_vtk(const std::filesystem::path& file, const Grid& grid, const std::vector<double>& eps_s,
               const FlowState& state);

}  // namespace gridfree
