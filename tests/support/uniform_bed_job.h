// SPDX-License-Identifier: GPL-3.0-or-later
// A continuum bed (PHYSICS.md §6 "uniform bed") for the solver tests:
// 10 × 120 × 10 d with d = 0.01 cm, periodic x and z, mass inflow U0 at
// y = 0, pressure outflow at the top, ε_s = φ everywhere, probes at y* = 20
// and 100 (≥ 10 cells from both ends on the 4 × 60 × 4 grid).
#pragma once

#include "flow/solve.h"

namespace gridfree::test_support {

inline JobSpec uniform_bed_job(double phi, double u0, DragLaw law) {
  JobSpec job;
  CaseSpec& c = job.case_spec;
  c.name = "uniform";
  c.domain_dp = {10, 120, 10};
  c.particle_diameter_cm = 0.01;
  c.gas = {1e-3, 2e-4};
  c.boundaries[0] = {BoundarySpec{BoundaryKind::kPeriodic}, BoundarySpec{BoundaryKind::kPeriodic}};
  c.boundaries[2] = c.boundaries[0];
  c.boundaries[1][0] = {BoundaryKind::kMassInflow, u0, 0};
  c.boundaries[1][1] = {BoundaryKind::kPressureOutflow, 0, 0};
  c.particles = UniformSpec{phi};
  c.probes = {20, 100};
  job.numerics.cells = {4, 60, 4};
  job.numerics.convection = Limiter::kSuperbee;
  job.numerics.drag = law;
  job.numerics.max_iterations = 2000;
  return job;
}

}  // namespace gridfree::test_support
