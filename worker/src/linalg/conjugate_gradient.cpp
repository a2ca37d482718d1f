// SPDX-License-Identifier: GPL-3.0-or-later
#include "linalg/conjugate_gradient.h"

#include <cmath>

#include "linalg/stencil_ops.h"
#include "linalg/vector_ops.h"

namespace gridfree {

namespace {

// r = b − A φ with b the (consistent) right-hand side of the workspace.
void true_residual(const Stencil7& s, const std::vector<double>& b, const std::vector<double>& phi,
                   std::vector<double>& r) {
  stencil_apply(s, phi, r);
  const std::size_t n = r.size();
#pragma omp parallel for schedule(static) if (n > 20000)
  for (std::size_t c = 0; c < n; ++c) r[c] = b[c] - r[c];
}

}  // namespace

LinearSolveStats preconditioned_cg(const Stencil7& s, std::vector<double>& phi,
                                   Preconditioner& preconditioner,
                                   const LinearSolverSettings& settings, bool singular,
                                   CgWorkspace& w) {
  LinearSolveStats stats;
  const std::size_t n = s.grid.cells();
  phi.resize(n, 0.0);
  // The right-hand side: s.b itself, or a consistent copy (mean removed)
  // for a singular system.
  const std::vector<double>* b = &s.b;
  w.initial = phi;
  if (singular) {
    w.b = s.b;
    remove_mean(w.b);
    remove_mean(phi);
    b = &w.b;
  }
  true_residual(s, *b, phi, w.r);
  const double norm_b = norm2(*b);
  double norm_r = norm2(w.r);
  const double reference = norm_b > 0 ? norm_b : norm_r;
  if (reference == 0 || !std::isfinite(reference)) {
    stats.converged = std::isfinite(reference);
    return stats;
  }
  stats.initial_residual = norm_r / reference;
  stats.final_residual = stats.initial_residual;
  const double target = settings.tolerance * reference;

  bool restart = true;
  double rz = 0;
  while (true) {
    if (norm_r <= target) {
      // Confirm on the true residual (the recurrence drifts by round-off).
      true_residual(s, *b, phi, w.r);
      norm_r = norm2(w.r);
      stats.final_residual = norm_r / reference;
      if (norm_r <= target || stats.iterations >= settings.max_iterations) break;
      restart = true;
    }
    if (stats.iterations >= settings.max_iterations) break;
    preconditioner.apply(w.r, w.z);
    if (singular) remove_mean(w.z);
    const double rz_new = dot(w.r, w.z);
    if (!std::isfinite(rz_new)) break;
    if (restart) {
      w.p = w.z;
      restart = false;
    } else {
      xpby(w.z, rz_new / rz, w.p);
    }
    rz = rz_new;
    stencil_apply(s, w.p, w.q);
    const double curvature = dot(w.p, w.q);
    if (!(curvature > 0) || !std::isfinite(curvature)) break;
    const double alpha = rz / curvature;
    norm_r = std::sqrt(cg_update(alpha, w.p, w.q, phi, w.r));
    ++stats.iterations;
    stats.final_residual = norm_r / reference;
    if (!std::isfinite(norm_r)) break;
  }
  if (singular) remove_mean(phi);
  stats.converged = stats.final_residual <= settings.tolerance;
  if (!all_finite(phi)) {
    phi = w.initial;
    stats.converged = false;
  }
  return stats;
}

}  // namespace gridfree
