// SPDX-License-Identifier: GPL-3.0-or-later
// A random dense packing of equal spheres by compression: growing
// diameters with overlap-energy minimisation, the soft-sphere jamming
// protocol (O'Hern, Silbert, Liu & Nagel, Phys. Rev. E 68, 011306, 2003;
// FIRE: Bitzek et al., Phys. Rev. Lett. 97, 170201, 2006), the
// time-stepped relative of Lubachevsky–Stillinger compression.
//
// 1. The centres of particles/dense_packing.h step 1 (random, sorted).
// 2. Stages: the diameter σ starts at start_fraction · d; at each stage the
//    harmonic overlap energy E = ½ Σ_pairs (σ − r)² + ½ Σ (overlap with a
//    bound or hole)² is minimised by FIRE (unit masses, lengths in d) until
//    the largest overlap is below tolerance · σ, then σ ← min(d, σ(1 +
//    growth)). Bounds and holes of the allowed set move out by (d − σ)/2,
//    so a sphere of diameter σ touches a wall where one of d would.
// 3. The last stage, at σ = d (1 + final_margin), ends when no overlap
//    exceeds final_tolerance · d < final_margin · d: every pair is then
//    farther apart than d, and dense_packing's remove_overlaps (which
//    pushes pairs closer than d(1 + 10⁻⁶)) only checks it, in one sweep.
//    (Ending at σ = d with overlaps of 10⁻³ d left the pushes 5 000
//    sweeps of work at ε_s = 0.60.)
//
// Every step is deterministic after step 1: same seed, same packing.
#pragma once

#include <cstddef>
#include <vector>

#include "particles/dense_packing.h"

namespace gridfree {

struct CompressionOptions {
  double start_fraction = 0.8;    // σ₀ / d
  double growth = 0.01;           // σ ← σ (1 + growth) per stage
  double tolerance = 0.01;        // largest overlap / σ that ends a stage
  double final_margin = 2e-4;     // the last stage's σ = d (1 + final_margin) ...
  double final_tolerance = 1e-4;  // ... and largest overlap / d that ends it
  long max_steps = 2000000;       // FIRE steps in all, then std::runtime_error
};

struct CompressionTrace {
  int stages = 0;
  long steps = 0;       // FIRE steps
  int final_sweeps = 0; // remove_overlaps' sweeps
};

std::vector<Vec3> compressed_dense_packing(const DensePackingRegion& region, double diameter, std::size_t n,
                                           ParticleRandom& rng, const CompressionOptions& options = {},
                                           CompressionTrace* trace = nullptr);

}  // namespace gridfree
