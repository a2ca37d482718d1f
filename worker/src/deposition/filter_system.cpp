// SPDX-License-Identifier: GPL-3.0-or-later
// Assembly of one backward-Euler step of the diffusion filter and the
// conservation correction; see filter_system.h for the equations.
// The assembly loop runs in parallel (each cell writes only its own
// entries); sums are sequential, so results do not depend on the thread count.
#include "deposition/filter_system.h"
#include "linalg/parallel_threshold.h"

#include <cmath>
#include <cstddef>

namespace gridfree::filter_detail {

Stencil7 assemble_filter_step(const Grid& grid, const std::array<double, 3>& nu, double dtau) {
  Stencil7 s(grid);
  std::array<double, 3> a{};
  for (int axis = 0; axis < 3; ++axis)
    if (nu[axis] > 0 && grid.n[axis] > 1) a[axis] = nu[axis] * dtau / (grid.h(axis) * grid.h(axis));
  const int nx = grid.n[0], ny = grid.n[1], nz = grid.n[2];
#pragma omp parallel for schedule(static) if (grid.cells() > kParallelCells)
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = grid.index(i, j, k);
        // A face on a non-periodic boundary carries no flux: its coefficient is 0.
        s.aw[c] = (i > 0 || grid.periodic[0]) ? a[0] : 0.0;
        s.ae[c] = (i < nx - 1 || grid.periodic[0]) ? a[0] : 0.0;
        s.as[c] = (j > 0 || grid.periodic[1]) ? a[1] : 0.0;
        s.an[c] = (j < ny - 1 || grid.periodic[1]) ? a[1] : 0.0;
        s.ab[c] = (k > 0 || grid.periodic[2]) ? a[2] : 0.0;
        s.at[c] = (k < nz - 1 || grid.periodic[2]) ? a[2] : 0.0;
        s.ap[c] = 1.0 + s.aw[c] + s.ae[c] + s.as[c] + s.an[c] + s.ab[c] + s.at[c];
      }
    }
  }
  return s;
}

double remove_mean_residual(const Stencil7& s, std::vector<double>& x) {
  std::vector<double> r(x.size());
  stencil_residual(s, x, r);
  long double r_sum = 0;
  for (double v : r) r_sum += v;
  const double shift = static_cast<double>(r_sum / static_cast<long double>(r.size()));
  for (double& v : x) v += shift;
  stencil_residual(s, x, r);
  double r2 = 0, b2 = 0;
  for (std::size_t c = 0; c < r.size(); ++c) {
    r2 += r[c] * r[c];
    b2 += s.b[c] * s.b[c];
  }
  return b2 > 0 ? std::sqrt(r2 / b2) : 0.0;
}

}  // namespace gridfree::filter_detail
