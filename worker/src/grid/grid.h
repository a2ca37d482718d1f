// SPDX-License-Identifier: GPL-3.0-or-later
// Uniform Cartesian grid of the domain [0,Lx]x[0,Ly]x[0,Lz] (cm).
//
// Cells are indexed (i, j, k), x fastest: index = (k*ny + j)*nx + i.
// Cell (i,j,k) spans [i*dx, (i+1)*dx] etc.; its centre is at (i+1/2)*dx.
// The staggered (MAC) velocity components live on faces; see flow/fields.h.
// Δ* = (V_domain / N_cells)^(1/3) / d  (PHYSICS.md, notation).
#pragma once

#include <array>
#include <cstddef>

namespace gridfree {

struct Grid {
  std::array<int, 3> n{1, 1, 1};            // cells per direction
  std::array<double, 3> length{1, 1, 1};    // domain lengths, cm
  std::array<bool, 3> periodic{false, false, false};

  double h(int axis) const { return length[axis] / n[axis]; }  // cell size Δ_axis
  double cell_volume() const { return h(0) * h(1) * h(2); }
  double face_area(int axis) const { return cell_volume() / h(axis); }
  std::size_t cells() const { return std::size_t(n[0]) * n[1] * n[2]; }
  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * n[1] + j) * n[0] + i;
  }
  // Dimensionless cell size (V_domain/N)^(1/3) / d.
  double delta_star(double particle_diameter) const;
  // Centre coordinate of cell c along axis.
  double centre(int axis, int c) const { return (c + 0.5) * h(axis); }
  // Index of the cell containing coordinate x along axis (clamped to the grid;
  // periodic axes wrap first).
  int cell_of(int axis, double x) const;
};

// Most cells along one direction a job may ask for (docs/LIMITS.md).
inline constexpr int kMaxCellsPerAxis = 1000000;
// Fewest cells along y, the flow direction (inflow at y_low to the outlet):
// the pressure drop needs at least two cells to be resolved at all.
inline constexpr int kMinFlowCells = 2;

// Cells per direction from a dimensionless cell size: round(L*/Δ*), at least 1;
// kMaxCellsPerAxis + 1 when L*/Δ* exceeds the limit (or is NaN), so
// callers can refuse it instead of meeting an overflowed int.
std::array<int, 3> cells_for_delta_star(const std::array<double, 3>& domain_dp, double delta_star);

}  // namespace gridfree
