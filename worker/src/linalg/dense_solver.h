// SPDX-License-Identifier: GPL-3.0-or-later
// Exact solve of a small 7-point system on the coarsest multigrid level:
// the stencil is assembled into a dense matrix and factored once with
// Eigen's LDLᵀ (symmetric, pivoted). For a singular system (A·1 = 0) the
// factored matrix is A + σ·11ᵀ with σ = mean(a_P)/N, which is positive
// definite; with a right-hand side of zero mean (removed here) its solution
// solves A x = b and has zero mean, since 1ᵀA = 0 gives σN·1ᵀx = 1ᵀb = 0.
#pragma once

#include <memory>
#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

class DenseSolver {
 public:
  DenseSolver();
  ~DenseSolver();
  DenseSolver(DenseSolver&&) noexcept;
  DenseSolver& operator=(DenseSolver&&) noexcept;

  void factor(const Stencil7& s, bool singular);
  // x = A⁻¹ b (the mean of b removed first when singular).
  void solve(const std::vector<double>& b, std::vector<double>& x);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gridfree
