// SPDX-License-Identifier: GPL-3.0-or-later
// F = ρ ε̄ u A on every face, ∇·u and the mass balance of a cell (mass_flux.h).
#include "flow/mass_flux.h"

#include "flow/parallel.h"

#include <algorithm>

namespace gridfree {

void compute_mass_fluxes(const FlowProblem& problem, const FlowState& state, FaceVector& flux) {
  const Grid& g = problem.grid;
  for (int a = 0; a < 3; ++a) {
    const double rho_area = problem.gas.rho * g.face_area(a);
    if (flux[a].size() != state.u[a].size()) flux[a] = FaceField(g, a, 0.0);
    const long n = static_cast<long>(flux[a].size());
    const auto& u = state.u[a].values;
    const auto& e = state.eps_face[a].values;
    auto& F = flux[a].values;
#pragma omp parallel for schedule(static) if (n > kMinParallel)
    for (long f = 0; f < n; ++f) F[std::size_t(f)] = rho_area * e[std::size_t(f)] * u[std::size_t(f)];
  }
}

namespace {
// Face indices (low, high) of cell c along axis a.
inline std::array<std::size_t, 2> cell_faces(const Grid& g, const FaceLayout& lay,
                                             std::array<int, 3> x, int a) {
  const std::size_t lo = lay.index(x);
  x[a] = (g.periodic[a] && x[a] + 1 == g.n[a]) ? 0 : x[a] + 1;
  return {lo, lay.index(x)};
}
}  // namespace

CellField velocity_divergence(const Grid& grid, const FaceVector& u) {
  CellField div(grid.cells(), 0.0);
  const long cells = static_cast<long>(grid.cells());
#pragma omp parallel for schedule(static) if (cells > kMinParallel)
  for (long c = 0; c < cells; ++c) {
    const std::array<int, 3> x = cell_coords(grid, std::size_t(c));
    double s = 0;
    for (int a = 0; a < 3; ++a) {
      const auto f = cell_faces(grid, u[a].layout, x, a);
      s += (u[a][f[1]] - u[a][f[0]]) / grid.h(a);
    }
    div[std::size_t(c)] = s;
  }
  return div;
}

double cell_mass_imbalance(const FlowProblem& problem, const FaceVector& flux, std::size_t c) {
  const Grid& g = problem.grid;
  const std::array<int, 3> x = cell_coords(g, c);
  double net = 0;
  for (int a = 0; a < 3; ++a) {
    const auto f = cell_faces(g, flux[a].layout, x, a);
    net += flux[a][f[1]] - flux[a][f[0]];
  }
  if (problem.sources && !problem.sources->mass.empty())
    net -= problem.sources->mass[c] * g.cell_volume();
  return net;
}

BoundaryFlux boundary_mass_flux(const FlowProblem& problem, const FaceVector& flux) {
  const Grid& g = problem.grid;
  BoundaryFlux out;
  for (int a = 0; a < 3; ++a) {
    if (g.periodic[a]) continue;
    const FaceLayout& lay = flux[a].layout;
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int fa = side == 0 ? 0 : g.n[a];
      for (int q = 0; q < lay.n[c]; ++q)
        for (int r = 0; r < lay.n[b]; ++r) {
          std::array<int, 3> x{};
          x[a] = fa;
          x[b] = r;
          x[c] = q;
          const double F = flux[a][lay.index(x)];
          const double outward = side == 0 ? -F : F;
          out.out += std::max(outward, 0.0);
          out.in += std::max(-outward, 0.0);
        }
    }
  }
  return out;
}

}  // namespace gridfree
