// SPDX-License-Identifier: GPL-3.0-or-later
// Cell and face fields of the staggered (MAC) grid, with their index maps.
//
// Pressure, ε_g, ε_s and β live at cell centres (CellField, Grid::index
// order). The velocity component along axis a lives on the faces normal to a
// (FaceField): along a there are n_a faces on a periodic axis (face 0 is the
// wrap face between cell n_a−1 and cell 0) and n_a + 1 on a non-periodic one
// (faces 0 and n_a are the domain boundaries). Face f along a lies between
// cell f−1 (its "low" cell L) and cell f (its "high" cell R); in the other two
// directions a face has the indices of its cells. Index order is x fastest:
//   face index = (k * nf_y + j) * nf_x + i.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "grid/grid.h"

namespace gridfree {

// Index map of the faces normal to `axis`.
struct FaceLayout {
  int axis = 0;
  std::array<int, 3> n{};  // faces per direction (n_a or n_a + 1 along axis)

  FaceLayout() = default;
  FaceLayout(const Grid& grid, int normal_axis);

  std::size_t size() const { return std::size_t(n[0]) * n[1] * n[2]; }
  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * n[1] + j) * n[0] + i;
  }
  std::size_t index(const std::array<int, 3>& c) const { return index(c[0], c[1], c[2]); }
  // The face grid as a Grid (same spacing), for the 7-point linear solvers.
  Grid as_grid(const Grid& cells) const;
};

// One value per cell (Grid::index order).
using CellField = std::vector<double>;

// One value per face normal to `layout.axis`.
struct FaceField {
  FaceLayout layout;
  std::vector<double> values;

  FaceField() = default;
  FaceField(const Grid& grid, int axis, double value = 0.0)
      : layout(grid, axis), values(layout.size(), value) {}
  double& operator[](std::size_t f) { return values[f]; }
  double operator[](std::size_t f) const { return values[f]; }
  std::size_t size() const { return values.size(); }
};

// The three staggered velocity components (or mass fluxes, or d coefficients).
using FaceVector = std::array<FaceField, 3>;

FaceVector make_face_vector(const Grid& grid, double value = 0.0);

// Cell indices (i,j,k) of flat index c.
inline std::array<int, 3> cell_coords(const Grid& grid, std::size_t c) {
  const int i = static_cast<int>(c % std::size_t(grid.n[0]));
  const std::size_t rest = c / std::size_t(grid.n[0]);
  const int j = static_cast<int>(rest % std::size_t(grid.n[1]));
  const int k = static_cast<int>(rest / std::size_t(grid.n[1]));
  return {i, j, k};
}

// Face indices (i,j,k) of flat face index f.
inline std::array<int, 3> face_coords(const FaceLayout& layout, std::size_t f) {
  const int i = static_cast<int>(f % std::size_t(layout.n[0]));
  const std::size_t rest = f / std::size_t(layout.n[0]);
  const int j = static_cast<int>(rest % std::size_t(layout.n[1]));
  const int k = static_cast<int>(rest / std::size_t(layout.n[1]));
  return {i, j, k};
}

// Gas velocity at cell centres: mean of the two faces of each component,
// u_cell_a(c) = ½ (u_a(face c_a) + u_a(face c_a + 1)).
std::array<CellField, 3> cell_centre_velocity(const Grid& grid, const FaceVector& u_face);

}  // namespace gridfree
