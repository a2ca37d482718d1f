// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/symmetric_solver.h"

#include <stdexcept>

#include "linalg/stencil_ops.h"

namespace gridfree {

SymmetricSolver::SymmetricSolver(SymmetricSolverOptions options)
    : options_(options), multigrid_(options.multigrid) {}

void SymmetricSolver::setup(const Stencil7& s) {
  check_stencil(s);
  stencil_ = &s;
  singular_ = stencil_is_singular(s);
  if (options_.preconditioner == SymmetricPreconditioner::kMultigrid)
    multigrid_.setup(s, singular_);
  else
    jacobi_.setup(s);
}

LinearSolveStats SymmetricSolver::solve(std::vector<double>& phi,
                                        const LinearSolverSettings& settings) {
  if (stencil_ == nullptr) throw std::logic_error("SymmetricSolver::solve before setup");
  Preconditioner& m = options_.preconditioner == SymmetricPreconditioner::kMultigrid
                          ? static_cast<Preconditioner&>(multigrid_)
                          : static_cast<Preconditioner&>(jacobi_);
  CgWorkspace work;  // freed on return: the caller's other phases reuse the memory
  return preconditioned_cg(*stencil_, phi, m, settings, singular_, work);
}

LinearSolveStats SymmetricSolver::solve(const Stencil7& s, std::vector<double>& phi,
                                        const LinearSolverSettings& settings) {
  setup(s);
  return solve(phi, settings);
}

std::vector<std::array<int, 3>> SymmetricSolver::level_sizes() const {
  if (options_.preconditioner != SymmetricPreconditioner::kMultigrid) return {};
  return multigrid_.level_sizes();
}

LinearSolveStats solve_symmetric(const Stencil7& s, std::vector<double>& phi,
                                 const LinearSolverSettings& settings) {
  SymmetricSolver solver;
  return solver.solve(s, phi, settings);
}

}  // namespace gridfree
