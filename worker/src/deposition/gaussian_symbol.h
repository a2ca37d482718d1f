// SPDX-License-Identifier: GPL-3.0-or-later
// The multiplier of the sampled-Gaussian filter (docs/TRANSFER.md,
// docs/PHYSICS.md §3.2): convolution along an axis of spacing Δ with the
// positive kernel
//
//   g_m = exp(−(mΔ)²/(2s²)) / Σ_m' exp(−(m'Δ)²/(2s²)),   m ∈ ℤ,
//
// whose DTFT (ω = kΔ, Poisson summation) is the periodised Gaussian symbol
//
//   ĝ(ω) = Σ_j exp(−a(ω + 2πj)²) / Σ_j exp(−a(2πj)²),   a = s²/(2Δ²),
//        = Σ_m exp(−m²/(4a)) cos(mω) / Σ_m exp(−m²/(4a))   (the same theta
//          function summed in space),
//
// normalised so that ĝ(0) = 1 exactly (Σ conserved). Each sum is truncated
// adaptively once its next term is below 1e-18 of its first (the terms decay
// like a Gaussian, so the neglected tail is < 2e-18 relative): the frequency
// form is used when a ≥ 1/(2π) (s ≳ 0.56Δ, a few j suffice: |j| ≤ 2 for
// s ≥ Δ) and the spatial form below it (|m| ≤ 6 there), so at most a
// handful of terms are summed either way.
//
// Variance of g: s²(1 − ε) with ε ≈ 8π²(s/Δ)² exp(−2π²s²/Δ²) (aliasing;
// ε < 3e-7 for s ≥ Δ, 0.13 at s = Δ/2); its higher cumulants are as small.
#pragma once

#include <vector>

namespace gridfree {

// ĝ(ω) for s/Δ = s_over_h ≥ 0 (s = 0: the identity, ĝ ≡ 1).
double sampled_gaussian_symbol(double omega, double s_over_h);

// The per-axis transform multipliers ĝ(ω_k)/N_axis in FFTW's order:
// periodic (R2HC, N = n) ω_k = 2πk/n — the half-complex slot k and n − k
// share ĝ(2πk/n) = ĝ(2π(n − k)/n); wall-bounded (REDFT10, N = 2n)
// ω_k = πk/n, the DCT-II of the half-sample symmetric extension: the same
// kernel reflected at the wall faces (method of images), as the gaussian
// pre-deposition does. `variance` = s², cm² (Δ = h, cm).
std::vector<double> gaussian_axis_factors(int n, double h, double variance, bool periodic);

// The variance of the normalised sampled kernel in units of Δ²,
// Σ m² g_m (direct sum in space, independent of the symbol; for tests).
double sampled_gaussian_variance_h2(double s_over_h);

}  // namespace gridfree
