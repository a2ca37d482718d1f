// SPDX-License-Identifier: GPL-3.0-or-later
// Centroid deposition (PHYSICS.md §3.1): ownership of cells, conservation of
// particle volume, and the ε_s > 1 failure of grid-coupled deposition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "deposition/centroid.h"

namespace gridfree {
namespace {

// Uniform in [lo, hi) from the raw 64-bit engine output (reproducible everywhere).
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

std::vector<Particle> random_particles(const Grid& g, int count, double d, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Particle> ps;
  for (int i = 0; i < count; ++i) {
    Particle p;
    p.x = uniform(rng, 0, g.length[0]);
    p.y = uniform(rng, 0, g.length[1]);
    p.z = uniform(rng, 0, g.length[2]);
    p.d = d * uniform(rng, 0.8, 1.2);
    ps.push_back(p);
  }
  return ps;
}

double particle_volume(const Particle& p) { return std::numbers::pi / 6.0 * p.d * p.d * p.d; }

TEST(Centroid, ConservesParticleVolume) {
  // Σ_c ε_s V_c = Σ_p V_p: each V_p lands in exactly one cell; only the
  // summation order differs, so the relative difference is round-off (1e-13).
  for (bool periodic : {false, true}) {
    Grid g;
    g.n = {7, 11, 5};
    g.length = {0.3, 0.7, 0.1};
    g.periodic = {periodic, false, periodic};
    const auto ps = random_particles(g, 5000, 0.01, 42);
    const auto eps_s = solids_fraction_centroid(g, ps);
    long double deposited = 0, total = 0;
    for (double e : eps_s) deposited += e * g.cell_volume();
    for (const auto& p : ps) total += particle_volume(p);
    EXPECT_NEAR(static_cast<double>(deposited), static_cast<double>(total), 1e-13 * static_cast<double>(total));
  }
}

TEST(Centroid, ParticleOnAFaceGoesToTheCellAbove) {
  // Cell i is [i Δ, (i+1) Δ): a centre exactly on face i Δ belongs to cell i,
  // one ulp below it to cell i − 1, for sizes whose Δ is not exact in binary.
  for (int n : {3, 7, 10, 13}) {
    Grid g;
    g.n = {n, 1, 1};
    g.length = {0.7, 1, 1};
    for (int i = 1; i < n; ++i) {
      Particle p;
      p.y = p.z = 0.5;
      p.x = i * g.h(0);
      EXPECT_EQ(cell_of_particle(g, p), g.index(i, 0, 0)) << "n=" << n << " face " << i;
      p.x = std::nextafter(p.x, 0.0);
      EXPECT_EQ(cell_of_particle(g, p), g.index(i - 1, 0, 0)) << "n=" << n << " below face " << i;
    }
  }
}

TEST(Centroid, BoundariesWrapOrClamp) {
  Grid g;
  g.n = {4, 4, 4};
  g.length = {1, 1, 1};
  g.periodic = {true, false, true};
  Particle p;
  p.x = 1.0;   // periodic: x = L is x = 0
  p.y = 1.0;   // wall: the high boundary belongs to the last cell
  p.z = -0.1;  // periodic: wraps to 0.9, cell 3
  EXPECT_EQ(cell_of_particle(g, p), g.index(0, 3, 3));
  p.x = -1e-18;  // wraps to just below L (rounds to L): cell 0, never out of range
  p.y = -0.5;    // outside a wall: clamped to cell 0
  p.z = 2.30;    // wraps to 0.3: cell 1
  EXPECT_EQ(cell_of_particle(g, p), g.index(0, 0, 1));
  p.x = 0.0;
  p.y = 0.25;  // on face 1 of y
  p.z = 0.0;
  EXPECT_EQ(cell_of_particle(g, p), g.index(0, 1, 0));
  p.y = 7.0;  // far outside a wall: last cell
  EXPECT_EQ(cell_of_particle(g, p), g.index(0, 3, 0));
}

TEST(Centroid, DepositsAnyQuantityPerCellVolume) {
  Grid g;
  g.n = {2, 2, 1};
  g.length = {2, 2, 1};
  std::vector<Particle> ps(3);
  ps[0].x = 0.5, ps[0].y = 0.5, ps[0].u = 3;
  ps[1].x = 0.7, ps[1].y = 0.2, ps[1].u = 4;
  ps[2].x = 1.5, ps[2].y = 1.5, ps[2].u = -1;
  for (auto& p : ps) p.z = 0.5;
  const auto sum_u = deposit_centroid(g, ps, [](const Particle& p) { return p.u; });
  // V_c = 1: cell (0,0) holds 3 + 4, cell (1,1) holds −1.
  EXPECT_DOUBLE_EQ(sum_u[g.index(0, 0, 0)], 7.0);
  EXPECT_DOUBLE_EQ(sum_u[g.index(1, 1, 0)], -1.0);
  EXPECT_DOUBLE_EQ(sum_u[g.index(1, 0, 0)], 0.0);
  EXPECT_DOUBLE_EQ(sum_u[g.index(0, 1, 0)], 0.0);
}

TEST(Centroid, FineGridsExceedUnitSolidsFraction) {
  // One particle of diameter d in a cube cell of side 0.5 d: ε_s = (π/6)/0.125 ≈ 4.19.
  // This is the failure of grid-coupled deposition below Δ* ≈ 1.
  Grid g;
  g.n = {4, 4, 4};
  g.length = {0.02, 0.02, 0.02};
  Particle p;
  p.x = p.y = p.z = 0.011;
  p.d = 0.01;
  const auto eps_s = solids_fraction_centroid(g, {p});
  EXPECT_NEAR(eps_s[g.index(2, 2, 2)], std::numbers::pi / 6.0 / 0.125, 1e-12);
  EXPECT_GT(eps_s[g.index(2, 2, 2)], 1.0);
}

}  // namespace
}  // namespace gridfree
