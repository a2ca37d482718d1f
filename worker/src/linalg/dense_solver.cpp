// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/dense_solver.h"

#include <Eigen/Dense>

#include "linalg/stencil_ops.h"

namespace gridfree {

struct DenseSolver::Impl {
  Eigen::LDLT<Eigen::MatrixXd> ldlt;
  Eigen::VectorXd rhs, x;
  bool singular = false;
};

DenseSolver::DenseSolver() : impl_(std::make_unique<Impl>()) {}
DenseSolver::~DenseSolver() = default;
DenseSolver::DenseSolver(DenseSolver&&) noexcept = default;
DenseSolver& DenseSolver::operator=(DenseSolver&&) noexcept = default;

void DenseSolver::factor(const Stencil7& s, bool singular) {
  const Grid& g = s.grid;
  const Eigen::Index n = static_cast<Eigen::Index>(g.cells());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  const int nx = g.n[0];
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j) {
      const RowNeighbours r = row_neighbours(g, j, k);
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = r.self + i;
        const std::size_t w = i > 0 ? c - 1 : (g.periodic[0] ? r.self + nx - 1 : c);
        const std::size_t e = i < nx - 1 ? c + 1 : (g.periodic[0] ? r.self : c);
        const auto row = static_cast<Eigen::Index>(c);
        a(row, row) += s.ap[c];
        a(row, static_cast<Eigen::Index>(w)) -= s.aw[c];
        a(row, static_cast<Eigen::Index>(e)) -= s.ae[c];
        a(row, static_cast<Eigen::Index>(r.south + i)) -= s.as[c];
        a(row, static_cast<Eigen::Index>(r.north + i)) -= s.an[c];
        a(row, static_cast<Eigen::Index>(r.bottom + i)) -= s.ab[c];
        a(row, static_cast<Eigen::Index>(r.top + i)) -= s.at[c];
      }
    }
  impl_->singular = singular;
  if (singular && n > 0) a.array() += a.diagonal().mean() / static_cast<double>(n);
  impl_->ldlt.compute(a);
  impl_->rhs.resize(n);
  impl_->x.resize(n);
}

void DenseSolver::solve(const std::vector<double>& b, std::vector<double>& x) {
  const Eigen::Index n = impl_->rhs.size();
  for (Eigen::Index i = 0; i < n; ++i) impl_->rhs[i] = b[static_cast<std::size_t>(i)];
  if (impl_->singular && n > 0) impl_->rhs.array() -= impl_->rhs.mean();
  impl_->x = impl_->ldlt.solve(impl_->rhs);
  x.resize(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = impl_->x[i];
}

}  // namespace gridfree
