// SPDX-License-Identifier: GPL-3.0-or-later
// Solver for symmetric positive (semi)definite 7-point systems — the
// pressure correction and the diffusion filter: preconditioned conjugate
// gradients (conjugate_gradient.h) with an aggregation-multigrid V-cycle
// (multigrid.h, the default) or Jacobi as preconditioner.
//
// A SymmetricSolver keeps its multigrid hierarchy between calls, so a solver
// that re-solves with the same coefficients (the filter) builds it once. The
// Krylov vectors live only during solve(): memory is not held between calls. The free
// function solve_symmetric (stencil.h) builds a fresh one per call.
//
// Singular systems are detected (stencil_is_singular: no Dirichlet part in
// any row) and solved in the zero-mean sense: the mean of b is removed and
// the returned φ has zero mean.
#pragma once

#include <array>
#include <vector>

#include "linalg/conjugate_gradient.h"
#include "linalg/multigrid.h"
#include "linalg/preconditioner.h"
#include "linalg/stencil.h"

namespace gridfree {

enum class SymmetricPreconditioner { kMultigrid, kJacobi };

struct SymmetricSolverOptions {
  SymmetricPreconditioner preconditioner = SymmetricPreconditioner::kMultigrid;
  MultigridOptions multigrid;
};

class SymmetricSolver {
 public:
  explicit SymmetricSolver(SymmetricSolverOptions options = {});

  // Checks the stencil and (re)builds the preconditioner for its coefficients.
  // The stencil is kept by pointer until the next setup().
  void setup(const Stencil7& s);
  // Solves A φ = s.b for the stencil given to setup(); φ is the initial guess.
  LinearSolveStats solve(std::vector<double>& phi, const LinearSolverSettings& settings);
  // setup(s) then solve.
  LinearSolveStats solve(const Stencil7& s, std::vector<double>& phi,
                         const LinearSolverSettings& settings);

  bool singular() const { return singular_; }
  // Multigrid level sizes, fine first (empty for Jacobi).
  std::vector<std::array<int, 3>> level_sizes() const;

 private:
  SymmetricSolverOptions options_;
  const Stencil7* stencil_ = nullptr;
  bool singular_ = false;
  MultigridPreconditioner multigrid_;
  JacobiPreconditioner jacobi_;
};

}  // namespace gridfree
