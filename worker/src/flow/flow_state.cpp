// SPDX-License-Identifier: GPL-3.0-or-later
// Face averages of cell quantities:  φ̄_face = ½ (φ_L + φ_R)  (MFiX), with the
// ghost value of boundary.h beyond a non-periodic boundary.
#include "flow/flow_state.h"

#include "flow/parallel.h"

#include <functional>

namespace gridfree {
namespace {

// φ̄ on every face normal to `axis`; `ghost(side, inside)` gives the ghost value.
void face_average(const Grid& grid, int axis, const CellField& cell,
                  const std::function<double(int, double)>& ghost, FaceField& out) {
  out = FaceField(grid, axis, 0.0);
  const FaceLayout lay = out.layout;
  const long faces = static_cast<long>(lay.size());
  const int na = grid.n[axis];
#pragma omp parallel for schedule(static) if (faces > kMinParallel)
  for (long f = 0; f < faces; ++f) {
    std::array<int, 3> c = face_coords(lay, std::size_t(f));
    const int fa = c[axis];
    double lo = 0, hi = 0;
    if (grid.periodic[axis]) {
      std::array<int, 3> l = c;
      l[axis] = fa == 0 ? na - 1 : fa - 1;
      lo = cell[grid.index(l[0], l[1], l[2])];
      hi = cell[grid.index(c[0], c[1], c[2])];
    } else if (fa == 0) {
      hi = cell[grid.index(c[0], c[1], c[2])];
      lo = ghost(0, hi);
    } else if (fa == na) {
      c[axis] = na - 1;
      lo = cell[grid.index(c[0], c[1], c[2])];
      hi = ghost(1, lo);
    } else {
      hi = cell[grid.index(c[0], c[1], c[2])];
      c[axis] = fa - 1;
      lo = cell[grid.index(c[0], c[1], c[2])];
    }
    out[std::size_t(f)] = 0.5 * (lo + hi);
  }
}

}  // namespace

void update_eps_faces(const FlowProblem& problem, FlowState& state) {
  for (int a = 0; a < 3; ++a) {
    const auto& sides = problem.bc[a];
    face_average(problem.grid, a, state.eps_g,
                 [&sides](int side, double inside) { return ghost_eps_g(sides[side], inside); },
                 state.eps_face[a]);
  }
}

void apply_fixed_faces(const FlowProblem& problem, FlowState& state) {
  const Grid& g = problem.grid;
  for (int a = 0; a < 3; ++a) {
    if (g.periodic[a]) continue;
    FaceField& u = state.u[a];
    const FaceLayout& lay = u.layout;
    for (long f = 0; f < static_cast<long>(lay.size()); ++f) {
      const std::array<int, 3> c = face_coords(lay, std::size_t(f));
      if (face_role(g, problem.bc, a, c[a]) != FaceRole::kFixed) continue;
      const int side = face_side(c[a]);
      u[std::size_t(f)] = fixed_face_velocity(problem.bc[a][side], side, state.eps_face[a][std::size_t(f)]);
    }
  }
}

}  // namespace gridfree
