// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/preconditioner.h"

#include "linalg/smoother.h"
#include "linalg/parallel_threshold.h"

namespace gridfree {

void JacobiPreconditioner::setup(const Stencil7& s) {
  const std::size_t n = s.ap.size();
  inverse_diagonal_.resize(n);
  for (std::size_t c = 0; c < n; ++c) inverse_diagonal_[c] = s.ap[c] != 0 ? 1.0 / s.ap[c] : 0.0;
}

void JacobiPreconditioner::apply(const std::vector<double>& r, std::vector<double>& z) {
  const std::size_t n = r.size();
  z.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t c = 0; c < n; ++c) z[c] = inverse_diagonal_[c] * r[c];
}

void GaussSeidelPreconditioner::apply(const std::vector<double>& r, std::vector<double>& z) {
  z.assign(r.size(), 0.0);
  // red, black, red: the forward sweep followed by its adjoint (the repeated
  // black step in between would change nothing).
  gauss_seidel_colour(*stencil_, r, z, 0, scratch_);
  gauss_seidel_colour(*stencil_, r, z, 1, scratch_);
  gauss_seidel_colour(*stencil_, r, z, 0, scratch_);
}

}  // namespace gridfree
