// SPDX-License-Identifier: GPL-3.0-or-later
// Index maps of the staggered face fields and the face-to-centre average.
#include "flow/fields.h"

#include "flow/parallel.h"

namespace gridfree {

FaceLayout::FaceLayout(const Grid& grid, int normal_axis) : axis(normal_axis), n(grid.n) {
  if (!grid.periodic[axis]) n[axis] += 1;
}

Grid FaceLayout::as_grid(const Grid& cells) const {
  Grid g = cells;
  g.n = n;
  for (int a = 0; a < 3; ++a) g.length[a] = cells.h(a) * n[a];
  return g;
}

FaceVector make_face_vector(const Grid& grid, double value) {
  return {FaceField(grid, 0, value), FaceField(grid, 1, value), FaceField(grid, 2, value)};
}

std::array<CellField, 3> cell_centre_velocity(const Grid& grid, const FaceVector& u_face) {
  std::array<CellField, 3> out;
  const long cells = static_cast<long>(grid.cells());
  for (int a = 0; a < 3; ++a) {
    out[a].assign(grid.cells(), 0.0);
    const FaceLayout& lay = u_face[a].layout;
    const int na = grid.n[a];
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
    for (long c = 0; c < cells; ++c) {
      std::array<int, 3> x = cell_coords(grid, std::size_t(c));
      const double lo = u_face[a][lay.index(x)];
      x[a] = (x[a] + 1 == na && grid.periodic[a]) ? 0 : x[a] + 1;
      const double hi = u_face[a][lay.index(x)];
      out[a][std::size_t(c)] = 0.5 * (lo + hi);
    }
  }
  return out;
}

}  // namespace gridfree
