// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/stencil_ops.h"
#include "linalg/parallel_threshold.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gridfree {

RowNeighbours row_neighbours(const Grid& g, int j, int k) {
  const int ny = g.n[1], nz = g.n[2];
  const int js = j > 0 ? j - 1 : (g.periodic[1] ? ny - 1 : j);
  const int jn = j < ny - 1 ? j + 1 : (g.periodic[1] ? 0 : j);
  const int kb = k > 0 ? k - 1 : (g.periodic[2] ? nz - 1 : k);
  const int kt = k < nz - 1 ? k + 1 : (g.periodic[2] ? 0 : k);
  return {g.index(0, j, k), g.index(0, js, k), g.index(0, jn, k), g.index(0, j, kb),
          g.index(0, j, kt)};
}

void stencil_apply(const Stencil7& s, const std::vector<double>& phi, std::vector<double>& y) {
  const Grid& g = s.grid;
  const int nx = g.n[0], ny = g.n[1], nz = g.n[2];
  y.resize(g.cells());
  const double* x = phi.data();
  const bool px = g.periodic[0];
  const int rows = ny * nz;
#pragma omp parallel for schedule(static) if (g.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int j = row % ny, k = row / ny;
    const RowNeighbours r = row_neighbours(g, j, k);
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = r.self + i;
      const std::size_t w = i > 0 ? c - 1 : (px ? r.self + nx - 1 : c);
      const std::size_t e = i < nx - 1 ? c + 1 : (px ? r.self : c);
      y[c] = s.ap[c] * x[c] - s.aw[c] * x[w] - s.ae[c] * x[e] - s.as[c] * x[r.south + i] -
             s.an[c] * x[r.north + i] - s.ab[c] * x[r.bottom + i] - s.at[c] * x[r.top + i];
    }
  }
}

void reshape_stencil(Stencil7& s, const Grid& g) {
  s.grid = g;
  for (std::vector<double>* v : {&s.ap, &s.aw, &s.ae, &s.as, &s.an, &s.ab, &s.at, &s.b}) v->resize(g.cells());
}

void stencil_residual(const Stencil7& s, const std::vector<double>& phi, std::vector<double>& r) {
  stencil_apply(s, phi, r);
  const std::size_t n = r.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t c = 0; c < n; ++c) r[c] = s.b[c] - r[c];
}

bool stencil_is_singular(const Stencil7& s, double relative_tolerance) {
  const std::size_t n = s.grid.cells();
  for (std::size_t c = 0; c < n; ++c) {
    const double sum = s.aw[c] + s.ae[c] + s.as[c] + s.an[c] + s.ab[c] + s.at[c];
    if (std::abs(s.ap[c] - sum) > relative_tolerance * std::abs(s.ap[c])) return false;
  }
  return true;
}

void check_stencil(const Stencil7& s) {
  const Grid& g = s.grid;
  const std::size_t n = g.cells();
  for (const auto* v : {&s.ap, &s.aw, &s.ae, &s.as, &s.an, &s.ab, &s.at, &s.b})
    if (v->size() != n)
      throw std::invalid_argument("stencil: array of size " + std::to_string(v->size()) +
                                  " for " + std::to_string(n) + " cells");
  const auto fail = [](const char* side, std::size_t c) {
    throw std::invalid_argument(std::string("stencil: non-zero coefficient across the ") + side +
                                " boundary (non-periodic) at cell " + std::to_string(c));
  };
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        if (!g.periodic[0] && i == 0 && s.aw[c] != 0) fail("x-low", c);
        if (!g.periodic[0] && i == g.n[0] - 1 && s.ae[c] != 0) fail("x-high", c);
        if (!g.periodic[1] && j == 0 && s.as[c] != 0) fail("y-low", c);
        if (!g.periodic[1] && j == g.n[1] - 1 && s.an[c] != 0) fail("y-high", c);
        if (!g.periodic[2] && k == 0 && s.ab[c] != 0) fail("z-low", c);
        if (!g.periodic[2] && k == g.n[2] - 1 && s.at[c] != 0) fail("z-high", c);
      }
}

double stencil_asymmetry(const Stencil7& s) {
  const Grid& g = s.grid;
  double worst = 0;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j) {
      const RowNeighbours r = row_neighbours(g, j, k);
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t c = r.self + i;
        const double scale = std::max(std::abs(s.ap[c]), 1e-300);
        const std::size_t e = i < g.n[0] - 1 ? c + 1 : r.self;
        if (i < g.n[0] - 1 || g.periodic[0])
          worst = std::max(worst, std::abs(s.ae[c] - s.aw[e]) / scale);
        if (j < g.n[1] - 1 || g.periodic[1])
          worst = std::max(worst, std::abs(s.an[c] - s.as[r.north + i]) / scale);
        if (k < g.n[2] - 1 || g.periodic[2])
          worst = std::max(worst, std::abs(s.at[c] - s.ab[r.top + i]) / scale);
      }
    }
  return worst;
}

}  // namespace gridfree
