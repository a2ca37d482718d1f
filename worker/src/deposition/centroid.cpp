// SPDX-License-Identifier: GPL-3.0-or-later
// Centroid (grid-coupled) deposition (PHYSICS.md §3.1):
//
//   q_c = Σ_{p : centre of p in c} q(p) / V_c,     ε_s(c) = Σ_{p∈c} (π d_p³/6) / V_c.
//
// Cell ownership along each axis: cell i is the half-open interval
// [x_i, x_{i+1}) with x_i = i Δ (Δ = L/n, the same products Grid uses), so a
// centre exactly on a face belongs to the cell above it. Periodic axes wrap
// x into [0, L) first (x = L is cell 0); non-periodic axes clamp, so a centre
// on the high boundary x = L (or a stray one outside) goes to the last cell.
// Σ_c q_c V_c = Σ_p q(p) holds up to the round-off of the sums.
#include "deposition/centroid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gridfree {
int centroid_cell_along(const Grid& grid, int axis, double x) {
  const int n = grid.n[axis];
  const double length = grid.length[axis];
  const double h = grid.h(axis);
  if (grid.periodic[axis] && std::isfinite(x)) {
    x = std::fmod(x, length);
    if (x < 0) x += length;
    if (x >= length) x = 0;  // x + L rounded up to L
  }
  // Clamp in floating point before the cast (no overflow for stray or NaN x).
  const double cell = std::floor(x / h);
  int c = cell >= 0 ? static_cast<int>(std::min(cell, double(n - 1))) : 0;
  // x/h may round across a face: settle against the face positions c·h.
  if (c + 1 < n && x >= (c + 1) * h) ++c;
  if (c > 0 && x < c * h) --c;
  return c;
}

std::size_t cell_of_particle(const Grid& grid, const Particle& p) {
  return grid.index(centroid_cell_along(grid, 0, p.x), centroid_cell_along(grid, 1, p.y),
                     centroid_cell_along(grid, 2, p.z));
}

std::vector<double> deposit_centroid(const Grid& grid, const std::vector<Particle>& particles,
                                     const std::function<double(const Particle&)>& q) {
  std::vector<double> field(grid.cells(), 0.0);
  for (const auto& p : particles) field[cell_of_particle(grid, p)] += q(p);
  const double inv_volume = 1.0 / grid.cell_volume();
  for (double& v : field) v *= inv_volume;
  return field;
}

std::vector<double> solids_fraction_centroid(const Grid& grid, const std::vector<Particle>& particles) {
  return deposit_centroid(grid, particles,
                          [](const Particle& p) { return std::numbers::pi / 6.0 * p.d * p.d * p.d; });
}

}  // namespace gridfree
