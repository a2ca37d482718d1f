// SPDX-License-Identifier: GPL-3.0-or-later
#include "grid/grid.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

double Grid::delta_star(double particle_diameter) const {
  const double volume = length[0] * length[1] * length[2];
  return std::cbrt(volume / static_cast<double>(cells())) / particle_diameter;
}

int Grid::cell_of(int axis, double x) const {
  if (periodic[axis]) {
    x = std::fmod(x, length[axis]);
    if (x < 0) x += length[axis];
  }
  const int c = static_cast<int>(std::floor(x / h(axis)));
  return std::clamp(c, 0, n[axis] - 1);
}

std::array<int, 3> cells_for_delta_star(const std::array<double, 3>& domain_dp, double delta_star) {
  std::array<int, 3> cells{};
  for (int a = 0; a < 3; ++a) {
    // Saturates instead of overflowing the int (callers refuse > kMaxCellsPerAxis).
    const double n = std::round(domain_dp[a] / delta_star);
    cells[a] = !(n <= static_cast<double>(kMaxCellsPerAxis)) ? kMaxCellsPerAxis + 1 : n >= 1 ? static_cast<int>(n) : 1;
  }
  return cells;
}

}  // namespace gridfree
