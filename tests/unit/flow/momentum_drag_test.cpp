// SPDX-License-Identifier: GPL-3.0-or-later
// The drag terms of the momentum assembly (flow/momentum.h): the face value
// of β and βv̄ is the mean of the face's two cells, with a zero-gradient
// ghost beyond a non-periodic boundary. Checked by assembling the same
// system with and without drag: with α_u = 1 the differences must be
//   Δa_P = V β̄_P   and   Δb_P = V (βv̄)‾_P   on every unknown face,
// computed here independently from the cell values.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/mass_flux.h"
#include "flow/momentum.h"

namespace gridfree {
namespace {

FlowProblem small_problem() {
  FlowProblem pb;
  pb.grid.n = {3, 4, 2};
  pb.grid.length = {0.3, 0.4, 0.2};
  pb.grid.periodic = {true, false, true};
  const BoundarySpec periodic{BoundaryKind::kPeriodic};
  BoundarySpec inflow{BoundaryKind::kMassInflow};
  inflow.superficial_velocity_cm_s = 5.0;
  const BoundarySpec outflow{BoundaryKind::kPressureOutflow};
  pb.bc[0] = {periodic, periodic};
  // Outflow on the low side: its boundary faces are unknowns whose low cell
  // is a ghost (the wrapped index would be the wrong cell).
  pb.bc[1] = {outflow, inflow};
  pb.bc[2] = {periodic, periodic};
  return pb;
}

// A state with a non-trivial velocity and pressure (values arbitrary but fixed).
FlowState small_state(const FlowProblem& pb) {
  const Grid& g = pb.grid;
  FlowState st;
  st.eps_g.assign(g.cells(), 0.0);
  st.p.assign(g.cells(), 0.0);
  for (std::size_t c = 0; c < g.cells(); ++c) {
    st.eps_g[c] = 0.6 + 0.03 * double(c % 7);
    st.p[c] = 10.0 - 0.5 * double(c);
  }
  st.u = make_face_vector(g, 0.0);
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < st.u[a].size(); ++f) st.u[a][f] = std::sin(1.0 + double(f) + a);
  st.drag.beta.assign(g.cells(), 0.0);
  update_eps_faces(pb, st);
  apply_fixed_faces(pb, st);
  return st;
}

// ½(φ_L + φ_R) of face f normal to `a`, zero-gradient ghosts (the test's own
// index arithmetic, not the assembly's).
double face_mean(const Grid& g, const std::vector<double>& cell, int a, std::size_t f) {
  const FaceLayout lay(g, a);
  std::array<int, 3> x = face_coords(lay, f);
  const int fa = x[a];
  std::array<int, 3> lo = x, hi = x;
  lo[a] = fa == 0 ? (g.periodic[a] ? g.n[a] - 1 : 0) : fa - 1;
  hi[a] = fa == g.n[a] ? g.n[a] - 1 : fa;
  return 0.5 * (cell[g.index(lo[0], lo[1], lo[2])] + cell[g.index(hi[0], hi[1], hi[2])]);
}

TEST(MomentumDrag, FaceDragIsTheMeanOfTheTwoCells) {
  const FlowProblem pb = small_problem();
  const Grid& g = pb.grid;
  FlowState without = small_state(pb);
  FlowState with = without;
  for (std::size_t c = 0; c < g.cells(); ++c) with.drag.beta[c] = 100.0 + 13.0 * double(c);
  for (int a = 0; a < 3; ++a) {
    with.drag.beta_v[a].assign(g.cells(), 0.0);
    for (std::size_t c = 0; c < g.cells(); ++c) with.drag.beta_v[a][c] = 7.0 * double(c) - 3.0 * a;
  }
  FaceVector flux;
  compute_mass_fluxes(pb, without, flux);
  const CellField div = velocity_divergence(g, without.u);
  const double V = g.cell_volume();
  int unknown_faces = 0;
  for (int a = 0; a < 3; ++a) {
    const Grid fg = FaceLayout(g, a).as_grid(g);
    MomentumSystem s0(fg), s1(fg);
    FaceField d0, d1;
    assemble_momentum(pb, without, flux, div, a, 1.0, s0, d0);
    assemble_momentum(pb, with, flux, div, a, 1.0, s1, d1);
    for (std::size_t f = 0; f < fg.cells(); ++f) {
      const int fa = face_coords(FaceLayout(g, a), f)[a];
      if (face_role(g, pb.bc, a, fa) == FaceRole::kFixed) continue;
      ++unknown_faces;
      const double beta = face_mean(g, with.drag.beta, a, f);
      const double beta_v = face_mean(g, with.drag.beta_v[a], a, f);
      // Round-off of a sum of terms of size ≤ |a_P|, |b_P|: a few ulps of them.
      EXPECT_NEAR(s1.eq.ap[f] - s0.eq.ap[f], V * beta, 1e-12 * std::abs(s1.eq.ap[f])) << a << " " << f;
      EXPECT_NEAR(s1.eq.b[f] - s0.eq.b[f], V * beta_v, 1e-12 * (std::abs(s1.eq.b[f]) + std::abs(s0.eq.b[f])))
          << a << " " << f;
    }
  }
  // Faces on the outflow boundary (zero-gradient ghost) are among them.
  EXPECT_GT(unknown_faces, int(g.cells()));
}

}  // namespace
}  // namespace gridfree
