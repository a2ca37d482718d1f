// SPDX-License-Identifier: GPL-3.0-or-later
// Exact pseudo-time diffusion filter by real transforms (spectral_filter.h).
// FFTW's row-major 3-D layout with dimensions (n_z, n_y, n_x) is exactly
// Grid::index order (x fastest). A separable r2r transform applies the 1-D
// transform along every axis; the multiplier is the product of the per-axis
// factors. Round trip scaling: R2HC∘HC2R = n, REDFT10∘REDFT01 = 2n.
#include "deposition/spectral_filter.h"

#include <cmath>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <utility>

#include <fftw3.h>

namespace gridfree {
namespace {

// FFTW's planner is not thread-safe: planning and destroying plans is
// serialised (executing a plan is thread-safe).
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

std::vector<double> spectral_axis_factors(int n, double h, double nu, bool periodic) {
  std::vector<double> f(std::size_t(n), 1.0);
  const double scale = periodic ? n : 2.0 * n;
  for (int k = 0; k < n; ++k) {
    const double s = periodic ? std::sin(std::numbers::pi * k / n) : std::sin(std::numbers::pi * k / (2.0 * n));
    const double lambda = -4.0 / (h * h) * s * s;
    f[std::size_t(k)] = (nu > 0 ? std::exp(nu * lambda) : 1.0) / scale;
  }
  return f;
}

struct SpectralFilter::Impl {
  Grid grid;
  std::array<std::vector<double>, 3> factor;
  double* buffer = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  ~Impl() {
    std::lock_guard lock(planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    if (buffer) fftw_free(buffer);
  }
};

namespace {

std::array<std::vector<double>, 3> diffusion_factors(const Grid& grid, const std::array<double, 3>& nu) {
  std::array<std::vector<double>, 3> f;
  for (int a = 0; a < 3; ++a)
    f[std::size_t(a)] = spectral_axis_factors(grid.n[a], grid.h(a), nu[std::size_t(a)], grid.periodic[a]);
  return f;
}

}  // namespace

SpectralFilter::SpectralFilter(const Grid& grid, const std::array<double, 3>& nu)
    : SpectralFilter(grid, diffusion_factors(grid, nu)) {}

SpectralFilter::SpectralFilter(const Grid& grid, std::array<std::vector<double>, 3> factor)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.grid = grid;
  for (int a = 0; a < 3; ++a)
    if (factor[std::size_t(a)].size() != std::size_t(grid.n[a]))
      throw std::invalid_argument("SpectralFilter: one factor per mode of each axis");
  m.factor = std::move(factor);
  const int dims[3] = {grid.n[2], grid.n[1], grid.n[0]};
  fftw_r2r_kind fwd[3], bwd[3];
  for (int a = 0; a < 3; ++a) {
    fwd[2 - a] = grid.periodic[a] ? FFTW_R2HC : FFTW_REDFT10;
    bwd[2 - a] = grid.periodic[a] ? FFTW_HC2R : FFTW_REDFT01;
  }
  std::lock_guard lock(planner_mutex());
  m.buffer = static_cast<double*>(fftw_malloc(sizeof(double) * grid.cells()));
  if (!m.buffer) throw std::bad_alloc();
  m.forward = fftw_plan_r2r(3, dims, m.buffer, m.buffer, fwd, FFTW_ESTIMATE);
  m.backward = fftw_plan_r2r(3, dims, m.buffer, m.buffer, bwd, FFTW_ESTIMATE);
  if (!m.forward || !m.backward) throw std::runtime_error("FFTW could not plan the filter transforms");
}

SpectralFilter::~SpectralFilter() = default;

void SpectralFilter::apply(std::vector<double>& field) {
  Impl& m = *impl_;
  const Grid& g = m.grid;
  if (field.size() != g.cells()) throw std::invalid_argument("SpectralFilter: field size does not match the grid");
  std::copy(field.begin(), field.end(), m.buffer);
  fftw_execute(m.forward);
  const auto& fx = m.factor[0];
  const auto& fy = m.factor[1];
  const auto& fz = m.factor[2];
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j) {
      const double fyz = fy[std::size_t(j)] * fz[std::size_t(k)];
      double* row = m.buffer + g.index(0, j, k);
      for (int i = 0; i < g.n[0]; ++i) row[i] *= fx[std::size_t(i)] * fyz;
    }
  fftw_execute(m.backward);
  std::copy(m.buffer, m.buffer + g.cells(), field.begin());
}

}  // namespace gridfree
