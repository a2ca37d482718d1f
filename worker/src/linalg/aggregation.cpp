// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/aggregation.h"

#include <algorithm>

#include "linalg/stencil_ops.h"
#include "linalg/parallel_threshold.h"

namespace gridfree {

namespace {

// Per-axis coupling strength: Σ over cells of (a_low + a_high) / 2.
std::array<double, 3> axis_strength(const Stencil7& s) {
  std::array<double, 3> strength{0, 0, 0};
  const std::size_t n = s.grid.cells();
  for (std::size_t c = 0; c < n; ++c) {
    strength[0] += s.aw[c] + s.ae[c];
    strength[1] += s.as[c] + s.an[c];
    strength[2] += s.ab[c] + s.at[c];
  }
  return strength;
}

// Pairs of cells; an odd count puts three cells in the last aggregate.
void pair_axis(int n, bool coarsen, std::vector<int>& start, std::vector<int>& map) {
  const int nc = coarsen ? std::max(1, n / 2) : n;
  start.resize(nc + 1);
  map.resize(n);
  for (int I = 0; I < nc; ++I) start[I] = coarsen ? 2 * I : I;
  start[nc] = n;
  for (int I = 0; I < nc; ++I)
    for (int i = start[I]; i < start[I + 1]; ++i) map[i] = I;
}

}  // namespace

Aggregation choose_aggregation(const Stencil7& fine, double semi_coarsening_ratio) {
  const Grid& g = fine.grid;
  const std::array<double, 3> strength = axis_strength(fine);
  double strongest = 0;
  for (int a = 0; a < 3; ++a)
    if (g.n[a] >= 2) strongest = std::max(strongest, strength[a]);
  Aggregation agg;
  agg.coarse = g;
  for (int a = 0; a < 3; ++a) {
    const bool coarsen = g.n[a] >= 2 && strength[a] >= semi_coarsening_ratio * strongest;
    pair_axis(g.n[a], coarsen, agg.start[a], agg.map[a]);
    agg.coarse.n[a] = static_cast<int>(agg.start[a].size()) - 1;
    agg.coarse.periodic[a] = g.periodic[a] && agg.coarse.n[a] > 1;
  }
  return agg;
}

void aggregate_coefficients(const Stencil7& fine, const Aggregation& agg, Stencil7& coarse) {
  const Grid& g = fine.grid;
  const Grid& cg = agg.coarse;
  const std::size_t nc = cg.cells();
  coarse.grid = cg;
  for (auto* v : {&coarse.ap, &coarse.aw, &coarse.ae, &coarse.as, &coarse.an, &coarse.ab,
                  &coarse.at, &coarse.b})
    v->assign(nc, 0.0);
  const int rows = cg.n[1] * cg.n[2];
  const auto& sx = agg.start[0];
  const auto& sy = agg.start[1];
  const auto& sz = agg.start[2];
  // A crossing coupling whose coarse neighbour is the aggregate itself (a
  // periodic axis reduced to one cell) is internal.
  const bool self_x = cg.n[0] == 1, self_y = cg.n[1] == 1, self_z = cg.n[2] == 1;
#pragma omp parallel for schedule(static) if (g.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int J = row % cg.n[1], K = row / cg.n[1];
    for (int I = 0; I < cg.n[0]; ++I) {
      double excess = 0, aw = 0, ae = 0, as = 0, an = 0, ab = 0, at = 0;
      for (int k = sz[K]; k < sz[K + 1]; ++k)
        for (int j = sy[J]; j < sy[J + 1]; ++j)
          for (int i = sx[I]; i < sx[I + 1]; ++i) {
            const std::size_t f = g.index(i, j, k);
            excess += fine.ap[f] - (fine.aw[f] + fine.ae[f] + fine.as[f] + fine.an[f] +
                                    fine.ab[f] + fine.at[f]);
            if (i == sx[I] && !self_x) aw += fine.aw[f];
            if (i == sx[I + 1] - 1 && !self_x) ae += fine.ae[f];
            if (j == sy[J] && !self_y) as += fine.as[f];
            if (j == sy[J + 1] - 1 && !self_y) an += fine.an[f];
            if (k == sz[K] && !self_z) ab += fine.ab[f];
            if (k == sz[K + 1] - 1 && !self_z) at += fine.at[f];
          }
      const std::size_t c = cg.index(I, J, K);
      coarse.aw[c] = aw;
      coarse.ae[c] = ae;
      coarse.as[c] = as;
      coarse.an[c] = an;
      coarse.ab[c] = ab;
      coarse.at[c] = at;
      coarse.ap[c] = excess + (aw + ae + as + an + ab + at);
    }
  }
}

void restrict_sum(const Grid& fine, const Aggregation& agg, const std::vector<double>& r_fine,
                  std::vector<double>& r_coarse) {
  const Grid& cg = agg.coarse;
  r_coarse.resize(cg.cells());
  const int rows = cg.n[1] * cg.n[2];
  const auto& sx = agg.start[0];
  const auto& sy = agg.start[1];
  const auto& sz = agg.start[2];
#pragma omp parallel for schedule(static) if (fine.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int J = row % cg.n[1], K = row / cg.n[1];
    for (int I = 0; I < cg.n[0]; ++I) {
      double total = 0;
      for (int k = sz[K]; k < sz[K + 1]; ++k)
        for (int j = sy[J]; j < sy[J + 1]; ++j) {
          const std::size_t base = fine.index(0, j, k);
          for (int i = sx[I]; i < sx[I + 1]; ++i) total += r_fine[base + i];
        }
      r_coarse[cg.index(I, J, K)] = total;
    }
  }
}

void prolong_add(const Grid& fine, const Aggregation& agg, double scale,
                 const std::vector<double>& x_coarse, std::vector<double>& x_fine) {
  const Grid& cg = agg.coarse;
  const int rows = fine.n[1] * fine.n[2];
  const auto& mx = agg.map[0];
#pragma omp parallel for schedule(static) if (fine.cells() > kParallelCells)
  for (int row = 0; row < rows; ++row) {
    const int j = row % fine.n[1], k = row / fine.n[1];
    const std::size_t base = fine.index(0, j, k);
    const std::size_t cbase = cg.index(0, agg.map[1][j], agg.map[2][k]);
    for (int i = 0; i < fine.n[0]; ++i) x_fine[base + i] += scale * x_coarse[cbase + mx[i]];
  }
}

}  // namespace gridfree
