// SPDX-License-Identifier: GPL-3.0-or-later
// The bursting-bubble baseline (PC1: 30 × 200 × 10 d, d = 0.01 cm,
// periodic x and z, U0 = 20 cm/s, generator bursting_bubble seed 1,
// probes at y* = 4 and 104; superbee, BVK, the default transfer with
// fwhm 6) on the grid of Δ* = delta_star, for the solver's verification
// tests. Steady tolerance 1e-5 and 2000 outer iterations unless the test
// sets its own.
#pragma once

#include "flow/solve.h"

namespace gridfree::test_support {

inline JobSpec bubble_baseline_job(double delta_star) {
  JobSpec job;
  CaseSpec& c = job.case_spec;
  c.name = "PC1";
  c.domain_dp = {30, 200, 10};
  c.particle_diameter_cm = 0.01;
  c.gas = {1e-3, 2e-4};
  c.boundaries[0] = {BoundarySpec{BoundaryKind::kPeriodic}, BoundarySpec{BoundaryKind::kPeriodic}};
  c.boundaries[2] = c.boundaries[0];
  c.boundaries[1][0] = {BoundaryKind::kMassInflow, 20, 0};
  c.boundaries[1][1] = {BoundaryKind::kPressureOutflow, 0, 0};
  GeneratorSpec gen;
  gen.kind = "bursting_bubble";
  gen.params = {{"kind", "bursting_bubble"}, {"seed", 1}};
  c.particles = gen;
  c.probes = {4, 104};
  job.numerics.cells = cells_for_delta_star(c.domain_dp, delta_star);
  job.numerics.convection = Limiter::kSuperbee;
  job.numerics.drag = DragLaw::kBvk;
  job.numerics.deposition = DepositionSpec{};  // the default transfer, fwhm 6 (docs/TRANSFER.md)
  job.numerics.tolerances.steady = 1e-5;
  job.numerics.max_iterations = 2000;
  return job;
}

// The baseline to the steady tolerance `steady` within 5000 outer
// iterations, for the tests that compare the fixed points of two solvers.
inline JobSpec bubble_fixed_point_job(double delta_star, double steady) {
  JobSpec job = bubble_baseline_job(delta_star);
  job.numerics.tolerances.steady = steady;
  job.numerics.max_iterations = 5000;
  return job;
}

}  // namespace gridfree::test_support
