// SPDX-License-Identifier: GPL-3.0-or-later
// The diffusion filter solved exactly in pseudo-time (docs/PHYSICS.md §3.2,
// docs/TRANSFER.md): the semi-discrete equation
//
//   dα/dτ = Σ_i ν_i δ²_i α,   τ ∈ [0, 1],   δ²_i the 3-point second difference,
//
// is diagonal in the eigenvectors of δ²_i: Fourier modes on a periodic axis,
// cosines cos(πk(i + ½)/n) (DCT-II, cell-centred zero flux) on a wall-bounded
// one, with eigenvalues
//
//   periodic:  λ_k = −(4/Δ²) sin²(πk/n),       Neumann:  λ_k = −(4/Δ²) sin²(πk/(2n)),
//
// so α(1) = T⁻¹ [Π_i exp(ν_i λ_{k_i})] T α(0). Using FFTW's real transforms
// (R2HC/HC2R periodic, REDFT10/REDFT01 Neumann; the half-complex pair of
// mode k shares λ_k), planned once per grid with FFTW_ESTIMATE on one
// thread, so the result is deterministic and independent of the thread
// count. The k = 0 factor is exactly 1, so Σ α is conserved to round-off;
// the cost is O(N log N) whatever ν_i τ/Δ_i².
//
// The same transforms apply any other per-axis multiplier, e.g. the sampled
// Gaussian's (gaussian_symbol.h): FilterIntegration::kGaussian.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "grid/grid.h"

namespace gridfree {

class SpectralFilter {
 public:
  // The semi-discrete diffusion exp(Σ_i ν_i δ²_i) (spectral_axis_factors).
  SpectralFilter(const Grid& grid, const std::array<double, 3>& nu);
  // Any separable multiplier: factor[a][k] for mode k of axis a, in FFTW's
  // order and including the round-trip scale 1/n (periodic) or 1/(2n) (wall).
  SpectralFilter(const Grid& grid, std::array<std::vector<double>, 3> factor);
  ~SpectralFilter();
  SpectralFilter(const SpectralFilter&) = delete;
  SpectralFilter& operator=(const SpectralFilter&) = delete;

  void apply(std::vector<double>& field);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The per-axis multipliers exp(ν λ_k)/N_axis (N = n periodic, 2n Neumann),
// index k = 0..n−1 in FFTW's order for that axis; exposed for tests.
std::vector<double> spectral_axis_factors(int n, double h, double nu, bool periodic);

}  // namespace gridfree
