// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/multigrid.h"

#include "linalg/smoother.h"
#include "linalg/stencil_ops.h"
#include "linalg/parallel_threshold.h"

namespace gridfree {

void MultigridPreconditioner::setup(const Stencil7& fine, bool singular) {
  fine_ = &fine;
  if (levels_.empty()) levels_.emplace_back();
  std::size_t count = 1;
  while (true) {
    const std::size_t cells = stencil(count - 1).grid.cells();
    if (cells <= options_.coarsest_cells || int(count) >= options_.max_levels) break;
    Aggregation agg = choose_aggregation(stencil(count - 1), options_.semi_coarsening_ratio);
    if (agg.coarse.cells() == cells) break;  // nothing left to coarsen
    // Existing levels keep their storage; emplace_back may move them.
    if (levels_.size() < count + 1) levels_.emplace_back();
    levels_[count - 1].to_coarse = std::move(agg);
    aggregate_coefficients(stencil(count - 1), levels_[count - 1].to_coarse, levels_[count].a);
    ++count;
  }
  levels_.resize(count);
  coarsest_.factor(stencil(count - 1), singular);
}

std::vector<std::array<int, 3>> MultigridPreconditioner::level_sizes() const {
  std::vector<std::array<int, 3>> sizes;
  for (std::size_t l = 0; l < levels_.size(); ++l) sizes.push_back(stencil(l).grid.n);
  return sizes;
}

void MultigridPreconditioner::apply(const std::vector<double>& r, std::vector<double>& z) {
  cycle(0, r, z);
}

void MultigridPreconditioner::cycle(std::size_t l, const std::vector<double>& rhs,
                                    std::vector<double>& x) {
  const Stencil7& a = stencil(l);
  if (l + 1 == levels_.size()) {
    coarsest_.solve(rhs, x);
    return;
  }
  Level& level = levels_[l];
  Level& next = levels_[l + 1];
  x.assign(a.grid.cells(), 0.0);
  for (int s = 0; s < options_.smoothing_sweeps; ++s)
    gauss_seidel_sweep(a, rhs, x, SweepOrder::kForward, level.scratch);
  stencil_apply(a, x, level.residual);
  const std::size_t n = rhs.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t c = 0; c < n; ++c) level.residual[c] = rhs[c] - level.residual[c];
  restrict_sum(a.grid, level.to_coarse, level.residual, next.rhs);
  cycle(l + 1, next.rhs, next.x);
  prolong_add(a.grid, level.to_coarse, options_.coarse_correction_scale, next.x, x);
  for (int s = 0; s < options_.smoothing_sweeps; ++s)
    gauss_seidel_sweep(a, rhs, x, SweepOrder::kBackward, level.scratch);
}

}  // namespace gridfree
