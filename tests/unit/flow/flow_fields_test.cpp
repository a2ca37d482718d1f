// SPDX-License-Identifier: GPL-3.0-or-later
// Staggered index maps, the face-to-centre average, deterministic sums and
// the dp_star probe (checked on fields whose answers are known exactly).
#include <gtest/gtest.h>

#include "flow/fields.h"
#include "flow/parallel.h"
#include "flow/probes.h"

namespace gridfree {
namespace {

Grid grid3(bool periodic_x) {
  Grid g;
  g.n = {3, 5, 2};
  g.length = {0.3, 0.5, 0.2};
  g.periodic = {periodic_x, false, true};
  return g;
}

TEST(FaceLayout, PeriodicAxesHaveNFacesOthersNPlusOne) {
  const Grid g = grid3(true);
  EXPECT_EQ(FaceLayout(g, 0).n, (std::array<int, 3>{3, 5, 2}));
  EXPECT_EQ(FaceLayout(g, 1).n, (std::array<int, 3>{3, 6, 2}));
  EXPECT_EQ(FaceLayout(g, 2).n, (std::array<int, 3>{3, 5, 2}));
  const FaceLayout lay(g, 1);
  for (std::size_t f = 0; f < lay.size(); ++f) EXPECT_EQ(lay.index(face_coords(lay, f)), f);
}

TEST(CellCentreVelocity, IsTheMeanOfTheTwoFaces) {
  const Grid g = grid3(true);
  FaceVector u = make_face_vector(g, 0.0);
  // u_y = y on the faces (face j at y = j Δy): the centre value is y_centre.
  for (std::size_t f = 0; f < u[1].size(); ++f) u[1][f] = face_coords(u[1].layout, f)[1] * g.h(1);
  // u_x = 1 on face 0 only (periodic wrap face): cells 0 and 2 get 1/2.
  for (std::size_t f = 0; f < u[0].size(); ++f) u[0][f] = face_coords(u[0].layout, f)[0] == 0 ? 1.0 : 0.0;
  const auto c = cell_centre_velocity(g, u);
  for (std::size_t i = 0; i < g.cells(); ++i) {
    const auto x = cell_coords(g, i);
    EXPECT_NEAR(c[1][i], g.centre(1, x[1]), 1e-15);
    EXPECT_DOUBLE_EQ(c[0][i], x[0] == 1 ? 0.0 : 0.5);
  }
}

TEST(DeterministicSum, MatchesASerialBlockedSum) {
  std::vector<double> v(100000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 1.0 / double(i + 1);
  double expected = 0;
  for (std::size_t b = 0; b < v.size(); b += kReductionBlock) {
    double s = 0;
    for (std::size_t i = b; i < std::min(v.size(), b + kReductionBlock); ++i) s += v[i];
    expected += s;
  }
  EXPECT_EQ(deterministic_sum(v.size(), [&](std::size_t i) { return v[i]; }), expected);
}

TEST(Probes, LinearPressureGivesTheExactDrop) {
  // p = 100 − 7 y (+ an x-dependent part with zero row mean): linear
  // interpolation is exact, also when extrapolating below the first centre.
  const Grid g = grid3(false);
  std::vector<double> p(g.cells());
  for (std::size_t c = 0; c < g.cells(); ++c) {
    const auto x = cell_coords(g, c);
    p[c] = 100 - 7 * g.centre(1, x[1]) + (x[0] - 1) * 3.0;
  }
  const double rho = 1e-3, u0 = 20;
  EXPECT_NEAR(dp_star(g, p, 0.12, 0.43, rho, u0), 7 * (0.43 - 0.12) / (rho * u0 * u0), 1e-9);
  EXPECT_NEAR(dp_star(g, p, 0.01, 0.49, rho, u0), 7 * (0.49 - 0.01) / (rho * u0 * u0), 1e-9);
}

}  // namespace
}  // namespace gridfree
