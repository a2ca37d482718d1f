// SPDX-License-Identifier: GPL-3.0-or-later
// Nested-start interpolation (flow/prolong.h): trilinear interpolation is
// exact for fields linear in the coordinates wherever the fine point lies
// between coarse lattice points, wraps on periodic axes, and is held
// constant beyond the last lattice point of a non-periodic axis.
#include <gtest/gtest.h>

#include <cmath>

#include "flow/prolong.h"

namespace gridfree {
namespace {

Grid box(std::array<int, 3> n, std::array<bool, 3> periodic) {
  Grid g;
  g.n = n;
  g.length = {2.0, 3.0, 1.0};
  g.periodic = periodic;
  return g;
}

double linear(double x, double y, double z) { return 1.0 + 2.0 * x - 3.0 * y + 0.5 * z; }

TEST(Prolong, CellValuesOfALinearFieldAreExactBetweenCoarseCentres) {
  const Grid coarse = box({4, 6, 2}, {false, false, false});
  const Grid fine = box({8, 12, 4}, {false, false, false});
  CellField p(coarse.cells());
  for (std::size_t c = 0; c < p.size(); ++c) {
    const auto x = cell_coords(coarse, c);
    p[c] = linear(coarse.centre(0, x[0]), coarse.centre(1, x[1]), coarse.centre(2, x[2]));
  }
  const CellField out = prolong_cells(coarse, p, fine);
  int checked = 0;
  for (std::size_t c = 0; c < out.size(); ++c) {
    const auto x = cell_coords(fine, c);
    const std::array<double, 3> pos{fine.centre(0, x[0]), fine.centre(1, x[1]), fine.centre(2, x[2])};
    bool inside = true;  // between the first and last coarse centre on every axis
    for (int a = 0; a < 3; ++a)
      inside = inside && pos[a] >= coarse.centre(a, 0) && pos[a] <= coarse.centre(a, coarse.n[a] - 1);
    if (!inside) continue;
    EXPECT_NEAR(out[c], linear(pos[0], pos[1], pos[2]), 1e-12);  // round-off of a few products
    ++checked;
  }
  EXPECT_EQ(checked, 6 * 10 * 2);  // fine centres strictly inside: 8−2, 12−2, 4−2
}

TEST(Prolong, BeyondTheLastCoarseCentreTheValueIsHeld) {
  const Grid coarse = box({2, 1, 1}, {false, false, false});
  const Grid fine = box({4, 1, 1}, {false, false, false});
  const CellField out = prolong_cells(coarse, {10.0, 20.0}, fine);
  EXPECT_DOUBLE_EQ(out[0], 10.0);  // x = 0.25 < first coarse centre 0.5
  EXPECT_DOUBLE_EQ(out[3], 20.0);  // x = 1.75 > last coarse centre 1.5
  EXPECT_DOUBLE_EQ(out[1], 12.5);  // x = 0.75: a quarter of the way
}

TEST(Prolong, PeriodicAxesWrap) {
  const Grid coarse = box({2, 1, 1}, {true, false, false});
  const Grid fine = box({4, 1, 1}, {true, false, false});
  const CellField out = prolong_cells(coarse, {10.0, 20.0}, fine);
  // x = 0.25 lies between the last coarse centre (1.5, seen at −0.5) and the
  // first (0.5): three quarters of the way from 20 to 10.
  EXPECT_DOUBLE_EQ(out[0], 12.5);
  EXPECT_DOUBLE_EQ(out[3], 17.5);
}

TEST(Prolong, FaceVelocitiesOfALinearFieldAreExactIncludingBoundaryFaces) {
  const Grid coarse = box({4, 6, 2}, {false, false, true});
  const Grid fine = box({8, 12, 4}, {false, false, true});
  FaceVector u = make_face_vector(coarse);
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < u[a].size(); ++f) {
      const auto x = face_coords(u[a].layout, f);
      std::array<double, 3> pos{};
      for (int b = 0; b < 3; ++b) pos[b] = b == a ? x[b] * coarse.h(b) : coarse.centre(b, x[b]);
      u[a][f] = a == 0 ? 3.0 * pos[0] : (a == 1 ? 1.0 - pos[1] : 2.0);  // z periodic: constant
    }
  const FaceVector out = prolong_faces(coarse, u, fine);
  for (int a = 0; a < 3; ++a) {
    ASSERT_EQ(out[a].size(), FaceLayout(fine, a).size());
    for (std::size_t f = 0; f < out[a].size(); ++f) {
      const auto x = face_coords(out[a].layout, f);
      const double along = x[a] * fine.h(a);
      const double expected = a == 0 ? 3.0 * along : (a == 1 ? 1.0 - along : 2.0);
      EXPECT_NEAR(out[a][f], expected, 1e-12) << "component " << a << " face " << f;
    }
  }
}

}  // namespace
}  // namespace gridfree
