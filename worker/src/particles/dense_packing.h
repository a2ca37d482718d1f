// SPDX-License-Identifier: GPL-3.0-or-later
// A random dense packing of equal spheres (ε_s up to ≈ 0.62) by overlap
// removal with growing diameters, the "collective rearrangement" family of
// jamming protocols (Jodrey & Tory, Phys. Rev. A 32, 2347, 1985; Clarke &
// Wiley, Phys. Rev. A 35, 4476, 1987):
//
// 1. n centres uniform in the allowed set (centre bounds, outside holes).
// 2. Sweeps in particle order (Gauss–Seidel): every pair closer than the
//    current diameter δ is pushed apart symmetrically along its line of
//    centres to exactly δ(1 + 2·10⁻⁶); a pushed centre is projected back
//    into the allowed set (out of a hole radially, then clamped to the
//    bounds, wrapped on periodic axes). A cell list with bins ≥ d finds
//    the pairs.
// 3. δ starts at start_fraction · d (default d) and grows by `growth` per
//    sweep until it reaches d; the sweeps go on at d until one sweep finds no pair closer
//    than d(1 + 10⁻⁶) and no centre outside the allowed set.
//
// No step is random after step 1, so the result is a function of the
// initial centres: same seed, same packing, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "particles/cell_list.h"
#include "particles/random.h"

namespace gridfree {

struct DensePackingRegion {
  Vec3 length{};                   // the box [0, L)
  std::array<bool, 3> periodic{};  // per axis
  Vec3 lo{}, hi{};                 // allowed centre interval on non-periodic axes
  std::vector<Vec3> holes;         // centres must stay ≥ hole_radius from each
  double hole_radius = 0;
};

struct DensePackingOptions {
  // Initial δ / d and growth per sweep, δ ← min(d, δ (1 + growth)). Growing
  // was measured slower than starting at d (ε_s 0.589 between walls: 0.8
  // growing by 0.4 % a sweep 1484 sweeps, 0.9 by 0.2 % 1352, 0.7 by 0.1 %
  // 1961, d from the start 1134; the same structure), hence the defaults.
  double start_fraction = 1.0;
  double growth = 0.0;
  double push_margin = 0.002;   // pairs are pushed apart to δ (1 + push_margin) ...
  double over_relaxation = 1.5;  // ... times this factor (successive over-relaxation)
  int max_sweeps = 20000;       // then std::runtime_error
};

struct DensePackingTrace {
  int sweeps = 0;  // sweeps until no overlap was left
};

// Throws std::runtime_error when the sweeps do not remove every overlap
// (the fraction is too close to jamming for this protocol).
// = random_packing_centres, then remove_overlaps.
std::vector<Vec3> random_dense_packing(const DensePackingRegion& region, double diameter, std::size_t n,
                                       ParticleRandom& rng, const DensePackingOptions& options = {},
                                       DensePackingTrace* trace = nullptr);

// Step 1: n centres uniform in the allowed set, sorted in slabs of one
// diameter (y, then z, then x).
std::vector<Vec3> random_packing_centres(const DensePackingRegion& region, double diameter, std::size_t n,
                                         ParticleRandom& rng);

// Steps 2–3 on the centres x (in place; their order is the sweeps' order).
void remove_overlaps(const DensePackingRegion& region, double diameter, std::vector<Vec3>& x, ParticleRandom& rng,
                     const DensePackingOptions& options = {}, DensePackingTrace* trace = nullptr);

}  // namespace gridfree
