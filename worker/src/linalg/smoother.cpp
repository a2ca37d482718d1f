// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/smoother.h"

#include "linalg/stencil_ops.h"
#include "linalg/parallel_threshold.h"

namespace gridfree {

namespace {

bool has_odd_periodic_axis(const Grid& g) {
  for (int a = 0; a < 3; ++a)
    if (g.periodic[a] && g.n[a] > 1 && g.n[a] % 2 == 1) return true;
  return false;
}

// New value of every cell of `colour`, reading x and writing out (out may be x).
void colour_update(const Stencil7& s, const std::vector<double>& rhs, const std::vector<double>& x,
                   std::vector<double>& out, int colour) {
  const Grid& g = s.grid;
  const int nx = g.n[0], ny = g.n[1], nz = g.n[2];
  const bool px = g.periodic[0];
  const double* xv = x.data();
  double* o = out.data();
  const int rows = ny * nz;
#pragma omp parallel for schedule(static) if (g.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int j = row % ny, k = row / ny;
    const RowNeighbours r = row_neighbours(g, j, k);
    for (int i = (colour + j + k) & 1; i < nx; i += 2) {
      const std::size_t c = r.self + i;
      if (s.ap[c] == 0) {
        o[c] = xv[c];
        continue;
      }
      const std::size_t w = i > 0 ? c - 1 : (px ? r.self + nx - 1 : c);
      const std::size_t e = i < nx - 1 ? c + 1 : (px ? r.self : c);
      const double sum = rhs[c] + s.aw[c] * xv[w] + s.ae[c] * xv[e] + s.as[c] * xv[r.south + i] +
                         s.an[c] * xv[r.north + i] + s.ab[c] * xv[r.bottom + i] +
                         s.at[c] * xv[r.top + i];
      o[c] = sum / s.ap[c];
    }
  }
}

void copy_colour(const Grid& g, const std::vector<double>& from, std::vector<double>& to,
                 int colour) {
  const int nx = g.n[0], ny = g.n[1], nz = g.n[2];
  const int rows = ny * nz;
#pragma omp parallel for schedule(static) if (g.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int j = row % ny, k = row / ny;
    const std::size_t base = g.index(0, j, k);
    for (int i = (colour + j + k) & 1; i < nx; i += 2) to[base + i] = from[base + i];
  }
}

}  // namespace

void gauss_seidel_colour(const Stencil7& a, const std::vector<double>& rhs, std::vector<double>& x,
                         int colour, std::vector<double>& scratch) {
  if (!has_odd_periodic_axis(a.grid)) {
    colour_update(a, rhs, x, x, colour);
    return;
  }
  scratch.resize(x.size());
  colour_update(a, rhs, x, scratch, colour);
  copy_colour(a.grid, scratch, x, colour);
}

void gauss_seidel_sweep(const Stencil7& a, const std::vector<double>& rhs, std::vector<double>& x,
                        SweepOrder order, std::vector<double>& scratch) {
  const int first = order == SweepOrder::kForward ? 0 : 1;
  gauss_seidel_colour(a, rhs, x, first, scratch);
  gauss_seidel_colour(a, rhs, x, 1 - first, scratch);
}

}  // namespace gridfree
