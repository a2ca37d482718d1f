// SPDX-License-Identifier: GPL-3.0-or-later
// Pressure probes: row averages and linear interpolation in y (probes.h).
#include "flow/probes.h"

#include <algorithm>
#include <cmath>

namespace gridfree {

double row_mean_pressure(const Grid& grid, const CellField& p, int j) {
  double s = 0;
  for (int k = 0; k < grid.n[2]; ++k)
    for (int i = 0; i < grid.n[0]; ++i) s += p[grid.index(i, j, k)];
  return s / (double(grid.n[0]) * grid.n[2]);
}

double mean_pressure_at(const Grid& grid, const CellField& p, double y) {
  const int ny = grid.n[1];
  if (ny == 1) return row_mean_pressure(grid, p, 0);
  const double hy = grid.h(1);
  // Row j0 with centre y_j0 ≤ y < y_j0+1 (clamped to [0, ny−2]).
  const int j0 = std::clamp(static_cast<int>(std::floor(y / hy - 0.5)), 0, ny - 2);
  const double t = (y - grid.centre(1, j0)) / hy;
  const double p0 = row_mean_pressure(grid, p, j0);
  const double p1 = row_mean_pressure(grid, p, j0 + 1);
  return p0 + t * (p1 - p0);
}

double dp_star(const Grid& grid, const CellField& p, double y1, double y2, double rho, double u0) {
  return (mean_pressure_at(grid, p, y1) - mean_pressure_at(grid, p, y2)) / (rho * u0 * u0);
}

}  // namespace gridfree
