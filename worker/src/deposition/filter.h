// SPDX-License-Identifier: GPL-3.0-or-later
// The grid-independent Gaussian filter (PHYSICS.md §3.2): implicit diffusion
//   ∂α/∂τ = ν_i ∂²α/∂x_i²,  τ ∈ [0, 1],
// with ν_i = max(δ_f² − Δ_i², 0)/(16 ln 2) ("seed", the paper's),
// max(σ² − c Δ_i², 0)/2 with σ² = δ_f²/(8 ln 2) and c the variance the
// pre-deposition kernel adds per Δ_i² ("consistent"), or δ_f²/(8√(2 ln 2))
// ("mfix"), zero flux at non-periodic boundaries, wrap on periodic ones.
// Backward Euler in `steps` equal pseudo-time steps, or solved exactly in
// pseudo-time by transforms (spectral_filter.h), or — `gaussian` — replaced
// by the convolution with the sampled Gaussian of variance s_i² = 2ν_i per
// axis, the kernel the diffusion approximates (gaussian_symbol.h), applied
// by the same transforms; conserves Σ α V.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/solve_stats.h"
#include "grid/grid.h"

namespace gridfree {

enum class FilterDiffusivity { kSeed, kMfix, kConsistent };
// The names of the integrations (job field numerics.deposition.integration)
// are in deposition/filter_integration.h.
enum class FilterIntegration { kSteps, kExact, kGaussian };

struct FilterSettings {
  double fwhm_cm = 0;                       // δ_f, cm
  FilterDiffusivity diffusivity = FilterDiffusivity::kSeed;
  // "consistent" only: the variance the pre-deposition kernel adds per Δ_i²
  // (1/12 centroid, 1/6 trilinear; deposition/transfer_stencils.h).
  double kernel_variance_per_h2 = 1.0 / 12.0;
  FilterIntegration integration = FilterIntegration::kSteps;
  // Backward-Euler steps over τ ∈ [0,1]. The variance is exact for any count,
  // but the kernel shape is not: one step's kernel is the modified-Helmholtz
  // Green's function (∝ e^{−r/ℓ}/r in 3-D, singular at the particle), so the
  // filtered field sharpens as the grid refines and the nonlinear drag
  // follows. Measured on the bursting bubble (PC1, superbee, BVK, fwhm 6):
  // one step gives dp* = 1001, 1083, 1245 at Δ* = 3.3, 1, 0.5 (no grid
  // convergence); eight steps give 1001, 1023, 1019. Eight steps cost ≈ 1.5×
  // the one-step solve time at Δ* = 1 (docs/BENCHMARKS.md).
  int steps = 8;
  double tolerance = 1e-10;                 // relative residual of each linear solve
  int max_iterations = 10000;               // per linear solve
};

struct FilterStats {
  int steps = 0;                   // backward-Euler steps taken (0 for exact integration)
  int total_iterations = 0;        // summed over steps
  double worst_final_residual = 0; // largest final relative residual of any step
  bool converged = true;           // every step's linear solve converged
  std::array<double, 3> nu{};      // ν_i used, cm^2 (pseudo-time unit 1)
};

// ν_i per direction for a grid and settings.
std::array<double, 3> filter_diffusivity(const Grid& grid, const FilterSettings& s);

// Filters `field` (one value per cell, Grid::index order) in place.
FilterStats apply_filter(const Grid& grid, const FilterSettings& s, std::vector<double>& field);

// The previous result of every backward-Euler step of one field, the initial
// guesses of its next filtering (warm start). A field that changes little
// between calls (β over the outer iterations) then costs a few iterations
// per step; the answer still meets the tolerance ||r|| ≤ tol·||α^n|| of
// each step, so only the round-off-sized result differs from a cold start.
struct FilterWarmStart {
  std::vector<std::vector<double>> steps;  // empty until the first apply()
};

// The same filter for several fields on one grid: the step matrix and the
// solver's multigrid hierarchy are built once, in the constructor, and reused
// by every apply() (e.g. ε_s, β and the three components of βv̄ each outer
// iteration). apply() gives exactly what apply_filter() gives.
class DiffusionFilter {
 public:
  DiffusionFilter(const Grid& grid, const FilterSettings& s);
  ~DiffusionFilter();
  DiffusionFilter(DiffusionFilter&&) noexcept;
  DiffusionFilter& operator=(DiffusionFilter&&) noexcept;

  FilterStats apply(std::vector<double>& field);
  // As apply(), starting each step from `warm` (when it holds one result per
  // step of this grid) and leaving this call's step results in it.
  FilterStats apply(std::vector<double>& field, FilterWarmStart& warm);
  const std::array<double, 3>& nu() const;
  bool active() const;  // false when no axis diffuses: apply() is then a no-op

 private:
  FilterStats apply_steps(std::vector<double>& field, FilterWarmStart* warm);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gridfree
