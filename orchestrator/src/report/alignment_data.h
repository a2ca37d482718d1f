// SPDX-License-Identifier: GPL-3.0-or-later
// The alignment check of a study as the report receives it (report_data.h):
// for one series and one of its grids, dp* of the grid and of each of its
// re-aligned variants (docs/TRANSFER.md "Alignment check").
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace gridfree {

struct AlignmentGrid {
  long long series_id = 0;
  int grid_index = 0;
  double delta_star = 0;                      // of the grid itself
  std::array<int, 3> cells{};                 // of the grid itself
  std::vector<std::optional<double>> dp_star; // the grid and every variant; empty = not converged (yet)
};

}  // namespace gridfree
