// SPDX-License-Identifier: GPL-3.0-or-later
// A 7-point finite-volume system on the cell grid of a Grid:
//
//   a_P φ_P = a_W φ_W + a_E φ_E + a_S φ_S + a_N φ_N + a_B φ_B + a_T φ_T + b_P
//
// (W/E = −x/+x, S/N = −y/+y, B/T = −z/+z neighbours). Neighbours across a
// periodic axis wrap; across a non-periodic boundary the coefficient must be
// 0 (boundary conditions are folded into a_P and b by the discretization).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/solve_stats.h"
#include "grid/grid.h"

namespace gridfree {

struct Stencil7 {
  explicit Stencil7(const Grid& g)
      : grid(g), ap(g.cells(), 0.0), aw(g.cells(), 0.0), ae(g.cells(), 0.0), as(g.cells(), 0.0),
        an(g.cells(), 0.0), ab(g.cells(), 0.0), at(g.cells(), 0.0), b(g.cells(), 0.0) {}
  Grid grid;
  std::vector<double> ap, aw, ae, as, an, ab, at, b;
};

// Pointers to the neighbour coefficient arrays by axis and side:
// nb[axis][0] the low neighbour (W, S, B), nb[axis][1] the high one (E, N, T).
inline std::array<std::array<std::vector<double>*, 2>, 3> neighbour_arrays(Stencil7& s) {
  return {{{&s.aw, &s.ae}, {&s.as, &s.an}, {&s.ab, &s.at}}};
}

// Puts `s` on grid `g`: every array resized to g.cells() (contents
// unspecified; storage reused when it fits). One system can so serve
// several grids in turn, e.g. the three staggered momentum components.
void reshape_stencil(Stencil7& s, const Grid& g);

// r = b + Σ a_nb φ_nb − a_P φ for every cell.
void stencil_residual(const Stencil7& s, const std::vector<double>& phi, std::vector<double>& r);

struct LinearSolverSettings {
  double tolerance = 1e-8;   // on ||r|| / ||b|| (||r0|| when b = 0)
  int max_iterations = 500;
};

// Symmetric systems (pressure correction, filter): conjugate gradients
// preconditioned by aggregation multigrid; O(N) work per solve. A system
// with no Dirichlet part in any row (Σ a_nb = a_P everywhere, e.g. fully
// periodic) is singular: the mean of b is ignored and φ returned with zero
// mean. To reuse the multigrid hierarchy across calls, or to choose the
// preconditioner, use SymmetricSolver (linalg/symmetric_solver.h).
LinearSolveStats solve_symmetric(const Stencil7& s, std::vector<double>& phi,
                                 const LinearSolverSettings& settings);

// Non-symmetric systems (momentum with convection): BiCGSTAB preconditioned
// by a symmetric red-black Gauss–Seidel sweep (options: linalg/bicgstab.h).
// Both solvers throw std::invalid_argument for a malformed stencil (wrong
// array sizes, coupling across a non-periodic boundary).
LinearSolveStats solve_general(const Stencil7& s, std::vector<double>& phi,
                               const LinearSolverSettings& settings);

}  // namespace gridfree
