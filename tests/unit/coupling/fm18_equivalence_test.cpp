// SPDX-License-Identifier: GPL-3.0-or-later
// The fm18 preset computes exactly what the solver computed before the
// transfer options existed (docs/TRANSFER.md): centroid deposition filtered
// by eight backward-Euler steps with the paper's ν, and drag from the values
// of the particle's cell. The reference is assembled here from the
// primitives (centroid sums, apply_filter, the drag law) and must agree
// bitwise for ε_s and β.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "coupling/drag_field.h"
#include "coupling/solids_fraction.h"
#include "deposition/centroid.h"

namespace gridfree {
namespace {

TEST(Fm18Preset, IsBitwiseThePapersTransfer) {
  Grid g;
  g.n = {5, 12, 3};
  g.length = {0.06, 0.144, 0.036};  // Δ = 1.2 d
  g.periodic = {true, false, true};
  const double d = 0.01;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Particle> ps;
  for (int p = 0; p < 200; ++p) ps.push_back({u(rng) * 0.06, u(rng) * 0.1, u(rng) * 0.036, d});
  ProblemList problems;
  const DepositionSpec fm18 = parse_deposition({{"preset", "fm18"}, {"fwhm_dp", 6}}, "/d", problems);
  ASSERT_TRUE(problems.empty());

  // ε_s.
  FilterSettings paper;
  paper.fwhm_cm = 6 * d;
  paper.diffusivity = FilterDiffusivity::kSeed;
  paper.steps = 8;
  paper.tolerance = 1e-10;
  std::vector<double> reference = solids_fraction_centroid(g, ps);
  apply_filter(g, paper, reference);
  const SolidsFraction sf = deposit_solids_fraction(g, ps, fm18, d, 1e-10);
  ASSERT_EQ(sf.eps_s.size(), reference.size());
  for (std::size_t c = 0; c < reference.size(); ++c) EXPECT_EQ(sf.eps_s[c], reference[c]) << c;

  // β from the cell's ε_g and cell-centre velocity.
  std::vector<double> eps(g.cells());
  std::array<std::vector<double>, 3> vel;
  for (std::size_t c = 0; c < g.cells(); ++c) eps[c] = 1 - sf.eps_s[c];
  for (auto& comp : vel) {
    comp.resize(g.cells());
    for (double& v : comp) v = 20 * u(rng);
  }
  const DragSettings drag{DragLaw::kBvk, d, 1e-3, 2e-4};
  std::vector<double> beta_ref(g.cells(), 0.0);
  for (const Particle& p : ps) {
    const std::size_t c = cell_of_particle(g, p);
    DragState st;
    st.eps_g = eps[c];
    st.slip = std::sqrt(vel[0][c] * vel[0][c] + vel[1][c] * vel[1][c] + vel[2][c] * vel[2][c]);
    st.d = p.d;
    st.rho_g = 1e-3;
    st.mu_g = 2e-4;
    const double f = drag_coefficient(DragLaw::kBvk, st) * (std::numbers::pi * p.d * p.d * p.d / 6.0);  // f_p = D V_p
    beta_ref[c] += f * (1.0 / g.cell_volume());
  }
  apply_filter(g, paper, beta_ref);
  TransferSettings t{kernel_params(fm18, d), fm18.sampling, filter_settings(fm18, d, 1e-10)};
  ParticleDragField field(g, ps, drag, t);
  DragField out;
  field.compute(eps, vel, out);
  for (std::size_t c = 0; c < g.cells(); ++c) EXPECT_EQ(out.beta[c], beta_ref[c]) << c;
}

}  // namespace
}  // namespace gridfree
