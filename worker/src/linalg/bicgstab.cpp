// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/bicgstab.h"

#include <cmath>
#include <limits>

#include "linalg/stencil_ops.h"
#include "linalg/vector_ops.h"
#include "linalg/parallel_threshold.h"

namespace gridfree {

namespace {

// Relative size below which an inner product counts as a breakdown.
constexpr double kBreakdown = 1e-12;

// y = a − α b.
void subtract_scaled(const std::vector<double>& a, double alpha, const std::vector<double>& b,
                     std::vector<double>& y) {
  const std::size_t n = a.size();
  y.resize(n);
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) y[i] = a[i] - alpha * b[i];
}

// p = r + β (p − ω v).
void update_direction(const std::vector<double>& r, double beta, double omega,
                      const std::vector<double>& v, std::vector<double>& p) {
  const std::size_t n = r.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) p[i] = r[i] + beta * (p[i] - omega * v[i]);
}

// x += α a + ω b.
void add_two(double alpha, const std::vector<double>& a, double omega,
             const std::vector<double>& b, std::vector<double>& x) {
  const std::size_t n = x.size();
#pragma omp parallel for schedule(static) if (n > kParallelCells)
  for (std::size_t i = 0; i < n; ++i) x[i] += alpha * a[i] + omega * b[i];
}

bool finite(double v) { return std::isfinite(v); }

}  // namespace

LinearSolveStats bicgstab(const Stencil7& s, std::vector<double>& phi,
                          Preconditioner& preconditioner, const LinearSolverSettings& settings,
                          int max_restarts) {
  LinearSolveStats stats;
  const std::size_t n = s.grid.cells();
  phi.resize(n, 0.0);
  // s = r − α v is formed in r itself (r is not needed once s exists): eight
  // vectors of n, not nine (docs/SOLVER.md "Memory").
  std::vector<double> r, r_hat, p(n, 0.0), v(n, 0.0), p_hat, s_hat, t;
  const std::vector<double> initial = phi;
  stencil_residual(s, phi, r);
  const double norm_b = norm2(s.b);
  double norm_r = norm2(r);
  const double reference = norm_b > 0 ? norm_b : norm_r;
  if (reference == 0 || !finite(reference)) {
    stats.converged = finite(reference);
    return stats;
  }
  const double target = settings.tolerance * reference;
  stats.initial_residual = stats.final_residual = norm_r / reference;

  int restarts = 0;
  bool fresh = true;
  double rho = 1, alpha = 1, omega = 1;
  while (stats.iterations < settings.max_iterations) {
    if (norm_r <= target) {
      stencil_residual(s, phi, r);  // confirm on the true residual
      norm_r = norm2(r);
      stats.final_residual = norm_r / reference;
      if (norm_r <= target) break;
      fresh = true;
    }
    if (fresh) {
      r_hat = r;
      std::fill(p.begin(), p.end(), 0.0);
      std::fill(v.begin(), v.end(), 0.0);
      rho = alpha = omega = 1;
      fresh = false;
    }
    const double rho_new = dot(r_hat, r);
    if (!finite(rho_new)) break;
    if (std::abs(rho_new) <= kBreakdown * norm2(r_hat) * norm_r) {
      if (++restarts > max_restarts) break;
      fresh = true;
      continue;
    }
    const double beta = (rho_new / rho) * (alpha / omega);
    rho = rho_new;
    update_direction(r, beta, omega, v, p);
    preconditioner.apply(p, p_hat);
    stencil_apply(s, p_hat, v);
    const double rv = dot(r_hat, v);
    if (!finite(rv) || std::abs(rv) <= kBreakdown * norm2(r_hat) * norm2(v)) {
      if (++restarts > max_restarts) break;
      fresh = true;
      continue;
    }
    alpha = rho / rv;
    if (!finite(alpha)) break;
    std::vector<double>& s_vec = r;  // s = r − α v, in place
    subtract_scaled(r, alpha, v, s_vec);
    const double norm_s = norm2(s_vec);
    if (!finite(norm_s)) break;
    ++stats.iterations;
    if (norm_s <= target) {
      axpy(alpha, p_hat, phi);
      norm_r = norm_s;
      stats.final_residual = norm_r / reference;
      continue;
    }
    preconditioner.apply(s_vec, s_hat);
    stencil_apply(s, s_hat, t);
    const double tt = dot(t, t);
    const double ts = dot(t, s_vec);
    omega = tt > 0 ? ts / tt : 0.0;
    if (!finite(omega)) break;
    add_two(alpha, p_hat, omega, s_hat, phi);
    subtract_scaled(s_vec, omega, t, r);  // r = s − ω t, in place
    norm_r = norm2(r);
    stats.final_residual = norm_r / reference;
    if (!finite(norm_r)) break;
    if (omega == 0) {
      if (++restarts > max_restarts) break;
      fresh = true;
    }
  }
  if (!all_finite(phi)) {
    // Cannot happen with finite scalars; kept as the last guard against NaN.
    phi = initial;
    stats.final_residual = stats.initial_residual;
  }
  stats.converged = stats.final_residual <= settings.tolerance;
  return stats;
}

LinearSolveStats solve_general(const Stencil7& s, std::vector<double>& phi,
                               const LinearSolverSettings& settings,
                               const GeneralSolverOptions& options) {
  check_stencil(s);
  if (options.preconditioner == GeneralPreconditioner::kJacobi) {
    JacobiPreconditioner m;
    m.setup(s);
    return bicgstab(s, phi, m, settings, options.max_restarts);
  }
  GaussSeidelPreconditioner m;
  m.setup(s);
  return bicgstab(s, phi, m, settings, options.max_restarts);
}

LinearSolveStats solve_general(const Stencil7& s, std::vector<double>& phi,
                               const LinearSolverSettings& settings) {
  return solve_general(s, phi, settings, GeneralSolverOptions{});
}

}  // namespace gridfree
