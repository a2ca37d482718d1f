// SPDX-License-Identifier: GPL-3.0-or-later
// Interphase force balance and uniform beds for every transfer
// (coupling/drag_field.h, docs/TRANSFER.md).
//
// 1. With matched kernels (trilinear deposition + trilinear sampling through
//    the exact filter; gaussian + gaussian) the force on the gas,
//    Σ_c V (β u_c − βv̄), equals the force on the particles, Σ_p f_p (u(p) − v_p),
//    to round-off: |ΔF|/|F| ≤ 1e-10 (the sums have ~10^3 terms of one sign
//    per component, round-off ≈ 1e-15 relative). The paper's transfer
//    (centroid + cell values + filter) does not balance: the check can fail.
// 2. A lattice with one particle at every cell centre is a uniform bed for
//    every kernel (the walls' images continue the lattice), so ε_s and β are
//    uniform, ε_s = V_p/V_c and β = ε_s D, to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "coupling/drag_field.h"
#include "coupling/solids_fraction.h"

namespace gridfree {
namespace {

Grid grid() {
  Grid g;
  g.n = {6, 10, 4};
  g.length = {0.06, 0.1, 0.04};  // Δ = 0.01 cm = d
  g.periodic = {true, false, true};
  return g;
}

struct Transfer {
  const char* name;
  DepositionSpec spec;
};

std::vector<Transfer> transfers() {
  std::vector<Transfer> t;
  DepositionSpec d;
  d.fwhm_dp = 3;
  t.push_back({"trilinear/trilinear/exact/consistent", d});
  DepositionSpec s = d;
  s.integration = FilterIntegration::kSteps;
  t.push_back({"trilinear/trilinear/steps", s});
  DepositionSpec gs = d;
  gs.pre_deposition = PreDeposition::kGaussian;
  gs.sampling = Sampling::kGaussian;
  t.push_back({"gaussian/gaussian", gs});
  DepositionSpec fm = d;
  fm.pre_deposition = PreDeposition::kCentroid;
  fm.sampling = Sampling::kCell;
  fm.diffusivity = FilterDiffusivity::kSeed;
  fm.integration = FilterIntegration::kSteps;
  t.push_back({"fm18", fm});
  return t;
}

TransferSettings settings_of(const DepositionSpec& d, double diameter) {
  TransferSettings t{kernel_params(d, diameter), d.sampling, std::nullopt};
  if (is_filtered(d)) t.filter = filter_settings(d, diameter, 1e-13);
  return t;
}

TEST(InterphaseForce, MatchedKernelsBalanceToRoundOff) {
  const Grid g = grid();
  const double d = 0.01;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Particle> ps;
  for (int p = 0; p < 300; ++p) {
    Particle q{u(rng) * 0.06, u(rng) * 0.1, u(rng) * 0.04, d};
    q.u = u(rng) - 0.5;
    q.v = u(rng);
    ps.push_back(q);
  }
  std::vector<double> eps(g.cells());
  std::array<std::vector<double>, 3> vel;
  for (double& e : eps) e = 0.5 + 0.4 * u(rng);
  for (auto& c : vel) {
    c.resize(g.cells());
    for (double& v : c) v = 5 + 20 * u(rng);
  }
  const DragSettings drag{DragLaw::kBvk, d, 1e-3, 2e-4};
  for (const Transfer& t : transfers()) {
    ParticleDragField field(g, ps, drag, settings_of(t.spec, d));
    DragField out;
    field.compute(eps, vel, out);
    if (std::string(t.name) == "fm18") {
      EXPECT_GT(field.last_imbalance(), 1e-4) << "the unmatched transfer should show its imbalance";
    } else if (t.spec.integration == FilterIntegration::kSteps) {
      EXPECT_LT(field.last_imbalance(), 1e-10) << t.name;  // iterative filter solved to 1e-13
    } else {
      EXPECT_LT(field.last_imbalance(), 1e-12) << t.name;
    }
  }
}

TEST(UniformLattice, EveryTransferGivesAUniformBed) {
  const Grid g = grid();
  const double d = 0.008;
  std::vector<Particle> ps;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) ps.push_back({g.centre(0, i), g.centre(1, j), g.centre(2, k), d});
  const double phi = std::numbers::pi / 6 * d * d * d / g.cell_volume();
  std::vector<double> eps(g.cells(), 1 - phi);
  std::array<std::vector<double>, 3> vel{std::vector<double>(g.cells(), 1.0), std::vector<double>(g.cells(), 30.0),
                                         std::vector<double>(g.cells(), 0.0)};
  const DragSettings drag{DragLaw::kBvk, d, 1e-3, 2e-4};
  DragField uniform;
  uniform_drag_field(g, drag, phi, eps, vel, uniform);
  std::vector<Transfer> all = transfers();
  DepositionSpec centroid;
  centroid.kind = DepositionKind::kCentroid;
  all.push_back({"centroid", centroid});
  for (const Transfer& t : all) {
    const SolidsFraction sf = deposit_solids_fraction(g, ps, t.spec, d, 1e-13);
    for (double e : sf.eps_s) EXPECT_NEAR(e, phi, 1e-12 * phi) << t.name;
    ParticleDragField field(g, ps, drag, settings_of(t.spec, d));
    DragField out;
    field.compute(eps, vel, out);
    for (std::size_t c = 0; c < g.cells(); ++c) EXPECT_NEAR(out.beta[c], uniform.beta[c], 1e-10 * uniform.beta[c]) << t.name;
  }
}

}  // namespace
}  // namespace gridfree
