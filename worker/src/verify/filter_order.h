// SPDX-License-Identifier: GPL-3.0-or-later
// Order of accuracy of the diffusion filter (PHYSICS.md §3.2).
//
// A smooth periodic field α0 = 1 + ½ sin(kx) + ⅓ cos(2ky) (k = 2π, box [0,1]²,
// one cell in z) is filtered with FWHM δ = 0.2 and S backward-Euler steps.
// Sampled Fourier modes are eigenvectors of the discrete operator, and the
// exact answer of the same S-step scheme in the continuum limit multiplies
// mode κ by (1 + ν0 κ²/S)^(−S), ν0 = δ²/(16 ln 2). The discrete filter
// differs by the 3-point Laplacian (κ² → (2/Δ)² sin²(κΔ/2)) and by the −Δ²
// in ν = (δ² − Δ²)/(16 ln 2): both O(Δ²), so the expected order is 2.
#pragma once

#include <vector>

#include "verify/order_study.h"

namespace gridfree {

// The study's description (equation, scheme, norm, expected order), no grids yet.
OrderStudy filter_order_study();
// One n×n×1 grid: the max-norm error, or why the filter solve failed.
GridOutcome filter_outcome(int n);

OrderStudy filter_order(const std::vector<int>& grids);

}  // namespace gridfree
