// SPDX-License-Identifier: GPL-3.0-or-later
// The grid-independent Gaussian filter (PHYSICS.md §3.2):
//
//   ∂α/∂τ = Σ_i ν_i ∂²α/∂x_i²,  τ ∈ [0, 1],
//   "seed": ν_i = max(δ_f² − Δ_i², 0) / (16 ln 2),   "mfix": ν_i = δ_f² / (8 √(2 ln 2)),
//   "consistent": ν_i = max(δ_f²/(8 ln 2) − c Δ_i², 0) / 2  (c: the pre-deposition kernel's variance per Δ_i²).
//
// A Gaussian of FWHM δ has variance δ²/(8 ln 2) and diffusion for unit time
// adds 2ν, hence 16 ln 2; −Δ_i² discounts the cell's own smearing.
// Backward Euler in `steps` equal steps Δτ = 1/steps, each
//   (I − Δτ Σ_i ν_i δ²_i) α^{n+1} = α^n
// with the 3-point second difference δ²_i (zero flux at non-periodic
// boundaries, wrap across periodic ones). On an unbounded or periodic line
// each step adds exactly 2 ν_i Δτ to the variance along axis i (Σ x² δ²α =
// Σ α δ²(x²) = 2Δ² Σ α), so the variance is right for any step count.
// Each step is solved by linalg's multigrid-preconditioned conjugate
// gradients; Σ α V is conserved to round-off (filter_system.h). Axes with
// ν_i = 0 or one cell are skipped; when none is left the field is returned
// untouched. Exact integration (FilterIntegration::kExact) replaces the steps
// by the transform solution of spectral_filter.h; Gaussian integration
// (kGaussian) by the sampled Gaussian of variance 2ν_i per axis applied by
// the same transforms (gaussian_symbol.h).
#include "deposition/filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <spdlog/spdlog.h>

#include "deposition/filter_system.h"
#include "deposition/gaussian_symbol.h"
#include "deposition/spectral_filter.h"
#include "linalg/symmetric_solver.h"

namespace gridfree {

std::array<double, 3> filter_diffusivity(const Grid& grid, const FilterSettings& s) {
  std::array<double, 3> nu{};
  if (!(s.fwhm_cm > 0)) return nu;
  const double fwhm2 = s.fwhm_cm * s.fwhm_cm;
  const double ln2 = std::numbers::ln2;
  for (int axis = 0; axis < 3; ++axis) {
    switch (s.diffusivity) {
      case FilterDiffusivity::kSeed:
        nu[axis] = std::max(fwhm2 - grid.h(axis) * grid.h(axis), 0.0) / (16.0 * ln2);
        break;
      case FilterDiffusivity::kMfix:
        nu[axis] = fwhm2 / (8.0 * std::sqrt(2.0 * ln2));
        break;
      case FilterDiffusivity::kConsistent:
        nu[axis] = std::max(fwhm2 / (8.0 * ln2) - s.kernel_variance_per_h2 * grid.h(axis) * grid.h(axis), 0.0) / 2.0;
        break;
    }
  }
  return nu;
}

struct DiffusionFilter::Impl {
  Impl(const Grid& g, const FilterSettings& settings)
      : s(settings), nu(filter_diffusivity(g, settings)), steps(std::max(1, settings.steps)) {
    for (int axis = 0; axis < 3; ++axis) active = active || (nu[axis] > 0 && g.n[axis] > 1);
    if (!active) return;  // nothing diffuses: Δ_i ≥ δ_f (or a single cell) on every axis
    if (settings.integration == FilterIntegration::kExact) {
      spectral = std::make_unique<SpectralFilter>(g, nu);
      return;
    }
    if (settings.integration == FilterIntegration::kGaussian) {
      std::array<std::vector<double>, 3> factor;
      for (int a = 0; a < 3; ++a)
        factor[std::size_t(a)] = gaussian_axis_factors(g.n[a], g.h(a), 2 * nu[std::size_t(a)], g.periodic[a]);
      spectral = std::make_unique<SpectralFilter>(g, std::move(factor));
      return;
    }
    system.emplace(filter_detail::assemble_filter_step(g, nu, 1.0 / steps));
    // The matrix is the same for every step and every field: set the solver
    // (and its multigrid hierarchy) up once; only the right-hand side changes.
    // Impl lives on the heap, so the solver's pointer to `system` stays valid.
    solver.setup(*system);
  }
  FilterSettings s;
  std::array<double, 3> nu;
  int steps;
  bool active = false;
  std::optional<Stencil7> system;  // only when active, backward-Euler steps
  std::unique_ptr<SpectralFilter> spectral;  // only when active, exact integration
  SymmetricSolver solver;
};

DiffusionFilter::DiffusionFilter(const Grid& grid, const FilterSettings& s)
    : impl_(std::make_unique<Impl>(grid, s)) {}
DiffusionFilter::~DiffusionFilter() = default;
DiffusionFilter::DiffusionFilter(DiffusionFilter&&) noexcept = default;
DiffusionFilter& DiffusionFilter::operator=(DiffusionFilter&&) noexcept = default;

const std::array<double, 3>& DiffusionFilter::nu() const { return impl_->nu; }
bool DiffusionFilter::active() const { return impl_->active; }

FilterStats DiffusionFilter::apply(std::vector<double>& field) { return apply_steps(field, nullptr); }

FilterStats DiffusionFilter::apply(std::vector<double>& field, FilterWarmStart& warm) {
  return apply_steps(field, &warm);
}

FilterStats DiffusionFilter::apply_steps(std::vector<double>& field, FilterWarmStart* warm) {
  Impl& m = *impl_;
  FilterStats stats;
  stats.nu = m.nu;
  if (!m.active) return stats;
  if (m.spectral) {
    m.spectral->apply(field);
    return stats;
  }
  const LinearSolverSettings linear{m.s.tolerance, m.s.max_iterations};
  const bool warm_ok =
      warm && warm->steps.size() == std::size_t(m.steps) && warm->steps.front().size() == field.size();
  if (warm && !warm_ok) warm->steps.assign(std::size_t(m.steps), {});
  for (int step = 0; step < m.steps; ++step) {
    m.system->b = field;  // α^n; the initial guess for α^{n+1} is α^n or the warm start
    if (warm_ok) field = warm->steps[std::size_t(step)];
    const LinearSolveStats solve = m.solver.solve(field, linear);
    const double residual = filter_detail::remove_mean_residual(*m.system, field);
    if (warm) warm->steps[std::size_t(step)] = field;
    ++stats.steps;
    stats.total_iterations += solve.iterations;
    stats.worst_final_residual = std::max(stats.worst_final_residual, residual);
    stats.converged = stats.converged && solve.converged;
  }
  if (!stats.converged)
    spdlog::warn("filter: linear solve did not reach {:g} in {} iterations (residual {:g})", m.s.tolerance,
                 m.s.max_iterations, stats.worst_final_residual);
  spdlog::debug("filter: nu = ({:g}, {:g}, {:g}) cm^2, {} steps, {} iterations", stats.nu[0], stats.nu[1],
                stats.nu[2], stats.steps, stats.total_iterations);
  return stats;
}

FilterStats apply_filter(const Grid& grid, const FilterSettings& s, std::vector<double>& field) {
  return DiffusionFilter(grid, s).apply(field);
}

}  // namespace gridfree
