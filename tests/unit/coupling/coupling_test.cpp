// SPDX-License-Identifier: GPL-3.0-or-later
// Solids fraction and drag field from particles (coupling/), against values
// computed here by hand: one particle's volume over one cell, β = φ D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "coupling/drag_field.h"
#include "coupling/solids_fraction.h"

namespace gridfree {
namespace {

Grid small_grid() {
  Grid g;
  g.n = {2, 2, 2};
  g.length = {0.02, 0.02, 0.02};  // Δ = 0.01 cm
  g.periodic = {true, false, true};
  return g;
}

TEST(SolidsFraction, CentroidFailsWhenACellIsOverfull) {
  const Grid g = small_grid();
  const double d = 0.02;  // particle larger than a cell: V_p / V_c = π·8/6 ≈ 4.19
  std::vector<Particle> ps{{0.015, 0.005, 0.005, d}};
  DepositionSpec dep;
  dep.kind = DepositionKind::kCentroid;
  const SolidsFraction sf = deposit_solids_fraction(g, ps, dep, d, 1e-10);
  EXPECT_NEAR(sf.max, std::numbers::pi * 8 / 6, 1e-12);
  EXPECT_EQ(sf.argmax, g.index(1, 0, 0));
  const auto reason = overfull_cell_reason(g, sf, d, true);
  ASSERT_TRUE(reason.has_value());
  EXPECT_NE(reason->find("solids fraction"), std::string::npos) << *reason;
  EXPECT_NE(reason->find("(1,0,0)"), std::string::npos) << *reason;
  EXPECT_NE(reason->find("diffusion deposition"), std::string::npos) << *reason;
}

TEST(SolidsFraction, UniformBedIsNotOverfull) {
  const SolidsFraction sf = uniform_solids_fraction(small_grid(), 0.4);
  EXPECT_DOUBLE_EQ(sf.max, 0.4);
  EXPECT_FALSE(overfull_cell_reason(small_grid(), sf, 0.01, false).has_value());
}

TEST(DragField, UniformBetaIsPhiTimesD) {
  const Grid g = small_grid();
  const DragSettings s{DragLaw::kWenYu, 0.01, 1e-3, 2e-4};
  std::vector<double> eps(g.cells(), 0.7);
  std::array<std::vector<double>, 3> u{std::vector<double>(g.cells(), 3.0),
                                       std::vector<double>(g.cells(), 4.0),
                                       std::vector<double>(g.cells(), 0.0)};
  DragField out;
  uniform_drag_field(g, s, 0.3, eps, u, out);
  DragState st;
  st.eps_g = 0.7;
  st.slip = 5.0;  // |(3, 4, 0)|
  st.d = 0.01;
  st.rho_g = 1e-3;
  st.mu_g = 2e-4;
  for (double b : out.beta) EXPECT_DOUBLE_EQ(b, 0.3 * drag_coefficient(DragLaw::kWenYu, st));
}

TEST(DragField, OneParticleDepositsItsDragCoefficientInItsCell) {
  const Grid g = small_grid();
  const DragSettings s{DragLaw::kBvk, 0.005, 1e-3, 2e-4};
  std::vector<Particle> ps{{0.005, 0.015, 0.005, 0.005, 0, 1.0, 0}};
  ParticleDragField field(g, ps, s, std::nullopt);
  std::vector<double> eps(g.cells(), 0.9);
  std::array<std::vector<double>, 3> u{std::vector<double>(g.cells(), 0.0),
                                       std::vector<double>(g.cells(), 3.0),
                                       std::vector<double>(g.cells(), 0.0)};
  DragField out;
  field.compute(eps, u, out);
  DragState st;
  st.eps_g = 0.9;
  st.slip = 2.0;  // |u − v_p| = 3 − 1
  st.d = 0.005;
  st.rho_g = 1e-3;
  st.mu_g = 2e-4;
  const double vp = std::numbers::pi * 0.005 * 0.005 * 0.005 / 6;
  const double f = drag_coefficient(DragLaw::kBvk, st) * vp / g.cell_volume();
  const std::size_t c = g.index(0, 1, 0);
  for (std::size_t i = 0; i < g.cells(); ++i) {
    EXPECT_DOUBLE_EQ(out.beta[i], i == c ? f : 0.0);
    EXPECT_DOUBLE_EQ(out.beta_v[1][i], i == c ? f * 1.0 : 0.0);
  }
}

TEST(DragField, FilteredBetaVIsVTimesBetaWhenEveryParticleMovesAlike) {
  // The filter is linear, so with one velocity v for every particle
  // filter(Σ f_p v / V) = v filter(Σ f_p / V): β (warm-started after the first
  // update) and βv̄ (filtered cold) must agree to the filter tolerance.
  Grid g;
  g.n = {8, 8, 8};
  g.length = {0.08, 0.08, 0.08};
  g.periodic = {true, false, true};
  const DragSettings s{DragLaw::kBvk, 0.005, 1e-3, 2e-4};
  const std::array<double, 3> v{0.5, -2.0, 1.0};
  std::vector<Particle> ps;
  for (int i = 0; i < 40; ++i) {
    const double t = 0.61803398875 * i - std::floor(0.61803398875 * i);  // spread over the box
    ps.push_back({0.004 + 0.072 * t, 0.004 + 0.0018 * i, 0.004 + 0.072 * (1 - t), 0.005, v[0], v[1], v[2]});
  }
  FilterSettings filter;
  filter.fwhm_cm = 0.03;
  filter.tolerance = 1e-12;
  ParticleDragField field(g, ps, s, filter);
  std::vector<double> eps(g.cells(), 0.9);
  std::array<std::vector<double>, 3> u{std::vector<double>(g.cells(), 0.1),
                                       std::vector<double>(g.cells(), 3.0),
                                       std::vector<double>(g.cells(), 0.0)};
  for (int update = 0; update < 2; ++update) {
    if (update == 1) u[1].assign(g.cells(), 3.3);  // a changed flow: β's filter starts warm
    DragField out;
    field.compute(eps, u, out);
    double beta_max = 0;
    for (double b : out.beta) beta_max = std::max(beta_max, b);
    ASSERT_GT(beta_max, 0.0);
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(out.beta_v[a].size(), g.cells());
      for (std::size_t c = 0; c < g.cells(); ++c)
        EXPECT_NEAR(out.beta_v[a][c], v[a] * out.beta[c], 1e-10 * beta_max) << "update " << update;
    }
  }
  EXPECT_EQ(field.updates(), 2);
}

}  // namespace
}  // namespace gridfree
