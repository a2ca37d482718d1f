// SPDX-License-Identifier: GPL-3.0-or-later
// Aggregation multigrid V-cycle used as a preconditioner for conjugate
// gradients (additive-correction multigrid, Hutchinson & Raithby 1986):
//
//   level 0 = the fine stencil; level l+1 = Pᵀ A_l P (aggregation.h),
//   until at most `coarsest_cells` cells remain; that level is solved exactly
//   (dense_solver.h).
//
// One application z = M⁻¹ r is a V-cycle from z = 0 on every level:
//   ν forward red-black Gauss–Seidel sweeps (red, black),
//   r_c = Pᵀ(rhs − A z), coarse cycle, z += ω P z_c,
//   ν backward sweeps (black, red).
// The post-smoother is the adjoint of the pre-smoother and the coarse
// correction is symmetric, so M⁻¹ is symmetric (and positive definite for
// 0 < ω < 2), as CG requires. ω > 1 (over-correction) compensates the
// piecewise-constant prolongation, which under-estimates smooth errors.
//
// setup() may be called again with new coefficients (same or another grid);
// storage is reused when the sizes are unchanged.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "linalg/aggregation.h"
#include "linalg/dense_solver.h"
#include "linalg/preconditioner.h"
#include "linalg/stencil.h"

namespace gridfree {

struct MultigridOptions {
  int smoothing_sweeps = 2;              // ν, symmetric sweeps before and after
  double coarse_correction_scale = 1.8;  // ω
  std::size_t coarsest_cells = 400;      // exact solve at or below this size
  double semi_coarsening_ratio = 0.25;   // coarsen an axis if its coupling ≥ ratio × strongest
  int max_levels = 30;
};

class MultigridPreconditioner final : public Preconditioner {
 public:
  explicit MultigridPreconditioner(MultigridOptions options = {}) : options_(options) {}

  // Builds the hierarchy for `fine` (kept by pointer: it must outlive use).
  void setup(const Stencil7& fine, bool singular);
  void apply(const std::vector<double>& r, std::vector<double>& z) override;

  // Cells per direction of every level, fine first.
  std::vector<std::array<int, 3>> level_sizes() const;

 private:
  struct Level {
    Stencil7 a{Grid{}};
    Aggregation to_coarse;  // from this level to the next (unused on the last)
    std::vector<double> rhs, x, residual, scratch;
  };
  const Stencil7& stencil(std::size_t l) const { return l == 0 ? *fine_ : levels_[l].a; }
  void cycle(std::size_t l, const std::vector<double>& rhs, std::vector<double>& x);

  MultigridOptions options_;
  const Stencil7* fine_ = nullptr;
  std::vector<Level> levels_;  // levels_[0].a is unused (the fine stencil is *fine_)
  DenseSolver coarsest_;
};

}  // namespace gridfree
