// SPDX-License-Identifier: GPL-3.0-or-later
// Residual, product and checks of the 7-point stencil (linalg/stencil_ops.h)
// against a hand-built 3×3×3 system evaluated here with explicit modular
// neighbour arithmetic, independently of the library's row bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "linalg/stencil_ops.h"

namespace gridfree {
namespace {

Grid grid333(bool px, bool py, bool pz) {
  Grid g;
  g.n = {3, 3, 3};
  g.length = {3, 3, 3};
  g.periodic = {px, py, pz};
  return g;
}

// Distinct coefficients per cell and side; zero across non-periodic sides.
Stencil7 hand_built(const Grid& g) {
  Stencil7 s(g);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const std::size_t c = g.index(i, j, k);
        const double base = 1 + i + 3 * j + 9 * k;
        s.aw[c] = (i > 0 || g.periodic[0]) ? 0.1 * base : 0;
        s.ae[c] = (i < 2 || g.periodic[0]) ? 0.2 * base : 0;
        s.as[c] = (j > 0 || g.periodic[1]) ? 0.3 * base : 0;
        s.an[c] = (j < 2 || g.periodic[1]) ? 0.4 * base : 0;
        s.ab[c] = (k > 0 || g.periodic[2]) ? 0.5 * base : 0;
        s.at[c] = (k < 2 || g.periodic[2]) ? 0.6 * base : 0;
        s.ap[c] = 3 * base + 1;
        s.b[c] = std::sin(double(c));
      }
  return s;
}

double expected_residual(const Stencil7& s, const std::vector<double>& phi, int i, int j, int k) {
  const Grid& g = s.grid;
  const auto at = [&](int a, int b, int c) {
    return phi[g.index((a + 3) % 3, (b + 3) % 3, (c + 3) % 3)];
  };
  const std::size_t c = g.index(i, j, k);
  // Non-periodic boundary coefficients are zero, so the wrapped value read
  // there is multiplied by zero.
  return s.b[c] + s.aw[c] * at(i - 1, j, k) + s.ae[c] * at(i + 1, j, k) +
         s.as[c] * at(i, j - 1, k) + s.an[c] * at(i, j + 1, k) + s.ab[c] * at(i, j, k - 1) +
         s.at[c] * at(i, j, k + 1) - s.ap[c] * phi[c];
}

class LinalgStencilResidual : public ::testing::TestWithParam<std::array<bool, 3>> {};

TEST_P(LinalgStencilResidual, MatchesHandEvaluation) {
  const auto p = GetParam();
  const Grid g = grid333(p[0], p[1], p[2]);
  const Stencil7 s = hand_built(g);
  std::vector<double> phi(27);
  for (std::size_t c = 0; c < 27; ++c) phi[c] = std::cos(0.7 * double(c)) + 0.1 * double(c);
  std::vector<double> r;
  stencil_residual(s, phi, r);
  ASSERT_EQ(r.size(), 27u);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        // Same sum in a different order: a few ulps of the largest term (~50).
        EXPECT_NEAR(r[g.index(i, j, k)], expected_residual(s, phi, i, j, k), 1e-12);
  std::vector<double> y;
  stencil_apply(s, phi, y);
  for (std::size_t c = 0; c < 27; ++c) EXPECT_NEAR(y[c], s.b[c] - r[c], 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Periodicity, LinalgStencilResidual,
                         ::testing::Values(std::array<bool, 3>{false, false, false},
                                           std::array<bool, 3>{true, false, true},
                                           std::array<bool, 3>{true, true, true},
                                           std::array<bool, 3>{false, true, false}));

TEST(LinalgStencilResidual, ExactValueAtOneCell) {
  // Cell (1,1,1) (index 13) by hand: base = 14, a_P = 43, neighbours 12, 14,
  // 10, 16, 4, 22 with φ = index, b = 0:
  // r = 1.4·12 + 2.8·14 + 4.2·10 + 5.6·16 + 7·4 + 8.4·22 − 43·13 = −158.6.
  const Grid g = grid333(false, false, false);
  Stencil7 s = hand_built(g);
  std::fill(s.b.begin(), s.b.end(), 0.0);
  std::vector<double> phi(27);
  for (std::size_t c = 0; c < 27; ++c) phi[c] = double(c);
  std::vector<double> r;
  stencil_residual(s, phi, r);
  EXPECT_NEAR(r[13], -158.6, 1e-12);
}

TEST(LinalgStencilChecks, SingularDetection) {
  const Grid g = grid333(true, true, true);
  Stencil7 s = hand_built(g);
  for (std::size_t c = 0; c < 27; ++c)
    s.ap[c] = s.aw[c] + s.ae[c] + s.as[c] + s.an[c] + s.ab[c] + s.at[c];
  EXPECT_TRUE(stencil_is_singular(s));
  s.ap[5] *= 1 + 1e-6;  // one row with a Dirichlet part
  EXPECT_FALSE(stencil_is_singular(s));
}

TEST(LinalgStencilChecks, RejectsCouplingAcrossNonPeriodicBoundary) {
  const Grid g = grid333(false, true, true);
  Stencil7 s = hand_built(g);
  EXPECT_NO_THROW(check_stencil(s));
  s.aw[g.index(0, 1, 1)] = 1.0;
  EXPECT_THROW(check_stencil(s), std::invalid_argument);
  Stencil7 short_b = hand_built(g);
  short_b.b.pop_back();
  EXPECT_THROW(check_stencil(short_b), std::invalid_argument);
}

TEST(LinalgStencilChecks, AsymmetryMeasure) {
  const Grid g = grid333(true, true, true);
  Stencil7 s(g);
  std::fill(s.ap.begin(), s.ap.end(), 6.0);
  for (auto* v : {&s.aw, &s.ae, &s.as, &s.an, &s.ab, &s.at}) std::fill(v->begin(), v->end(), 1.0);
  EXPECT_EQ(stencil_asymmetry(s), 0.0);
  s.ae[g.index(2, 0, 0)] = 1.6;  // couples across the x wrap to cell (0,0,0)
  EXPECT_NEAR(stencil_asymmetry(s), 0.1, 1e-15);
}

}  // namespace
}  // namespace gridfree
