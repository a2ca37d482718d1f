// The grid-independent Gaussian filter (PHYSICS.md §3.2): implicit diffusion
//   ∂α/∂τ = ν_i ∂²α/∂x_i²,  τ ∈ [0, 1],
// with ν_i = max(δ_f² − Δ_i², 0)/(16 ln 2) ("seed") or δ_f²/(8√(2 ln 2))
// ("mfix"), zero flux at non-periodic boundaries, wrap on periodic ones.
// Backward Euler in `steps` equal pseudo-time steps; conserves Σ α V.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/solve_stats.h"
#include "grid/grid.h"

namespace gridfree {

enum class FilterDiffusivity { kSeed, kMfix };

struct FilterSettings {
  double fwhm_cm = 0;                       // δ_f, cm
  FilterDiffusivity diffusivity = FilterDiffusivity::kSeed;
  int steps = 1;                            // backward-Euler steps over τ ∈ [0,1]
  double tolerance = 1e-10;                 // relative residual of each linear solve
  int max_iterations = 10000;               // per linear solve
};

struct FilterStats {
  int steps = 0;
  int total_iterations = 0;        // summed over steps
  double worst_final_residual = 0; // largest final relative residual of any step
  bool converged = true;           // every step's linear solve converged
  std::array<double, 3> nu{};      // ν_i used, cm^2 (pseudo-time unit 1)
};

// ν_i per direction for a grid and settings.
std::array<double, 3> filter_diffusivity(const Grid& grid, const FilterSettings& s);

// Filters `field` (one value per cell, Grid::index order) in place.
FilterStats apply_filter(const Grid& grid, const FilterSettings& s, std::vector<double>& field);

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
  const std::array<double, 3>& nu() const;
  bool active() const;  // false when no axis diffuses: apply() is then a no-op

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gridfree
