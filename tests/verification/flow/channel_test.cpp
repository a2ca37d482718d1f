// SPDX-License-Identifier: GPL-3.0-or-later
// Plane Poiseuille flow and the code-verification hook (docs/SOLVER.md).
//
// A channel with no-slip walls at x = 0 and x = L, periodic in y and z, no
// particles (ε_g = 1, β = 0), driven by a uniform manufactured momentum
// source S in y (FlowSources, the verification hook; the pressure level is
// fixed by its mean since nothing flows in or out). Exact solution:
//   μ d²v/dx² = −S  ⇒  v(x) = S x (L − x) / (2μ).
// The 3-point Laplacian is exact for a parabola; the no-slip ghost value
// (−v_P) is a linear extrapolation, so the error is O(Δx²): the observed
// order over 3 grids must be within 0.2 of 2.
//
// Second check: a fully periodic box with a prescribed uniform β and a
// source S gives v = S/β exactly (the drag balances the source).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "flow/simple_loop.h"

namespace gridfree {
namespace {

constexpr double kMu = 2e-4, kRho = 1e-3, kL = 0.1, kS = 1e-3;

FlowProblem channel(int nx, FlowSources& sources) {
  FlowProblem pb;
  pb.grid.n = {nx, 4, 1};
  pb.grid.length = {kL, 0.05, 0.02};
  pb.grid.periodic = {false, true, true};
  pb.bc[0] = {BoundarySpec{BoundaryKind::kWall}, BoundarySpec{BoundaryKind::kWall}};
  pb.bc[1] = {BoundarySpec{BoundaryKind::kPeriodic}, BoundarySpec{BoundaryKind::kPeriodic}};
  pb.bc[2] = pb.bc[1];
  pb.gas = {kRho, kMu, {0, 0, 0}};
  pb.convection = Limiter::kSuperbee;
  sources.momentum[1].assign(FaceLayout(pb.grid, 1).size(), kS);
  pb.sources = &sources;
  return pb;
}

FlowState rest_state(const Grid& g) {
  FlowState st;
  st.eps_g.assign(g.cells(), 1.0);
  st.p.assign(g.cells(), 0.0);
  st.u = make_face_vector(g, 0.0);
  st.drag.beta.assign(g.cells(), 0.0);
  return st;
}

SimpleSettings tight() {
  SimpleSettings s;
  s.steady_tolerance = 1e-10;
  s.max_iterations = 3000;
  return s;
}

// Max |v − v_exact| over the y-faces (at x = (i + ½)Δx).
double channel_error(int nx) {
  FlowSources sources;
  const FlowProblem pb = channel(nx, sources);
  FlowState st = rest_state(pb.grid);
  const SimpleOutcome out = run_simple(pb, tight(), st, {}, {}, {});
  EXPECT_EQ(out.status, SolveStatus::kConverged) << out.reason;
  const FaceLayout& lay = st.u[1].layout;
  double err = 0;
  for (std::size_t f = 0; f < lay.size(); ++f) {
    const double x = pb.grid.centre(0, face_coords(lay, f)[0]);
    err = std::max(err, std::abs(st.u[1][f] - kS * x * (kL - x) / (2 * kMu)));
  }
  return err;
}

TEST(Channel, PoiseuilleProfileConvergesAtSecondOrder) {
  const double e1 = channel_error(8), e2 = channel_error(16), e3 = channel_error(32);
  const double p12 = std::log2(e1 / e2), p23 = std::log2(e2 / e3);
  std::printf("errors %.3e %.3e %.3e, observed orders %.3f %.3f (peak velocity %.4f cm/s)\n", e1, e2, e3, p12,
              p23, kS * kL * kL / (8 * kMu));
  EXPECT_NEAR(p23, 2.0, 0.2);
  EXPECT_NEAR(p12, 2.0, 0.2);
}

TEST(PeriodicBox, PrescribedDragBalancesTheSource) {
  FlowProblem pb;
  pb.grid.n = {4, 6, 3};
  pb.grid.length = {0.04, 0.06, 0.03};
  pb.grid.periodic = {true, true, true};
  for (auto& axis : pb.bc) axis = {BoundarySpec{BoundaryKind::kPeriodic}, BoundarySpec{BoundaryKind::kPeriodic}};
  pb.gas = {kRho, kMu, {0, 0, 0}};
  FlowSources sources;
  sources.momentum[1].assign(FaceLayout(pb.grid, 1).size(), kS);
  sources.mass.assign(pb.grid.cells(), 0.0);
  pb.sources = &sources;
  FlowState st = rest_state(pb.grid);
  st.eps_g.assign(pb.grid.cells(), 0.6);
  const double beta = 50.0;
  st.drag.beta.assign(pb.grid.cells(), beta);
  const SimpleOutcome out = run_simple(pb, tight(), st, {}, {}, {});
  ASSERT_EQ(out.status, SolveStatus::kConverged) << out.reason;
  for (std::size_t f = 0; f < st.u[1].size(); ++f) EXPECT_NEAR(st.u[1][f], kS / beta, 1e-9 * kS / beta);
  double mean_p = 0;
  for (double p : st.p) mean_p += p;
  EXPECT_NEAR(mean_p, 0.0, 1e-12);
}

}  // namespace
}  // namespace gridfree
