// SPDX-License-Identifier: GPL-3.0-or-later
// The quantity of interest (PHYSICS.md §7):
//
//   dp_star = [p̄(y1) − p̄(y2)] / (ρ_g U0²),
//
// p̄(y) = x–z area average of the cell-centre pressure, linearly interpolated
// between the two rows of cell centres that bracket y. Below the first or
// above the last row of centres, the two nearest rows are extrapolated
// linearly. With gravity, p includes the gas head.
#pragma once

#include "flow/fields.h"
#include "grid/grid.h"

namespace gridfree {

// Area average of p over the x–z row of cells j (deterministic order).
double row_mean_pressure(const Grid& grid, const CellField& p, int j);

// p̄ at height y (cm).
double mean_pressure_at(const Grid& grid, const CellField& p, double y);

// dp_star for probes y1, y2 (cm), gas density rho and superficial velocity U0.
double dp_star(const Grid& grid, const CellField& p, double y1, double y2, double rho, double u0);

}  // namespace gridfree
