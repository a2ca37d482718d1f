// SPDX-License-Identifier: GPL-3.0-or-later
// Uniform continuum beds (PHYSICS.md §6): periodic x, z; mass inflow at
// y = 0; pressure outflow at the top. Away from the inlet every face carries
// u = U0/ε_g and the 1-D momentum balance gives exactly
//   dp/dy = −β u / ε_g,   β = φ D(ε_g, u)   (drag_coefficient, Model A),
// so dp_star_exact = (β u/ε_g)(y2 − y1)/(ρ U0²), computed here independently
// of the solver from drag_coefficient. The probes lie ≥ 10 cells from both
// ends, where the flow is exactly uniform, so only the steady tolerance
// (1e-7 here) separates the two: 1e-4 relative leaves a wide margin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "drag/drag_law.h"
#include "flow/solve.h"
#include "uniform_bed_job.h"

namespace gridfree {
namespace {

JobSpec uniform_bed(double phi, double u0, DragLaw law) {
  JobSpec job = test_support::uniform_bed_job(phi, u0, law);
  job.numerics.tolerances.steady = 1e-7;
  return job;
}

double exact_dp_star(const JobSpec& job, double phi, double u0) {
  const CaseSpec& c = job.case_spec;
  const double eps = 1 - phi;
  const double u = u0 / eps;
  DragState s;
  s.eps_g = eps;
  s.slip = u;
  s.d = c.particle_diameter_cm;
  s.rho_g = c.gas.density_g_cm3;
  s.mu_g = c.gas.viscosity_g_cm_s;
  const double beta = phi * drag_coefficient(job.numerics.drag, s);
  const double dy = (c.probes.y2_dp - c.probes.y1_dp) * c.particle_diameter_cm;
  return beta * u / eps * dy / (c.gas.density_g_cm3 * u0 * u0);
}

struct Case {
  double phi, u0;
};

TEST(UniformBed, EveryDragLawAtTwoReynoldsNumbers) {
  for (const auto& info : drag_laws()) {
    for (const Case& k : {Case{0.3, 20.0}, Case{0.45, 200.0}}) {
      const JobSpec job = uniform_bed(k.phi, k.u0, info.law);
      // Cold start (u = 0, p = 0): the iterations, not the warm start, find the answer.
      SolveOptions options;
      options.cold_start = true;
      const JobResult r = solve_with_particles(job, ParticleSet{}, options);
      SCOPED_TRACE(std::string(info.name) + " phi=" + std::to_string(k.phi) + " U0=" + std::to_string(k.u0));
      ASSERT_EQ(r.status, SolveStatus::kConverged) << r.reason;
      ASSERT_TRUE(r.dp_star.has_value());
      const double exact = exact_dp_star(job, k.phi, k.u0);
      EXPECT_NEAR(*r.dp_star / exact, 1.0, 1e-4) << "dp_star " << *r.dp_star << " exact " << exact
                                                 << " iterations " << r.iterations;
      std::printf("%-16s phi %.2f U0 %5.0f  dp_star %.8g exact %.8g  iterations %d\n",
                  std::string(info.name).c_str(), k.phi, k.u0, *r.dp_star, exact, r.iterations);
      // Mass conservation: inflow = outflow to the solver tolerance.
      EXPECT_LT(r.mass_imbalance, 1e-6);
    }
  }
}

// With gravity the balance gains the gas head, ε_g dp/dy = ε_g ρ g_y − β u:
//   dp_star = (β u/ε_g − ρ g_y)(y2 − y1)/(ρ U0²),
// and an empty domain is hydrostatic, dp_star = −g_y (y2 − y1)/U0².
TEST(UniformBed, GravityAddsTheGasHead) {
  const double g_y = -981.0;
  for (const Case& k : {Case{0.0, 20.0}, Case{0.3, 20.0}}) {
    JobSpec job = uniform_bed(k.phi, k.u0, DragLaw::kBvk);
    job.case_spec.gravity_cm_s2 = {0, g_y, 0};
    SolveOptions options;
    options.cold_start = true;
    const JobResult r = solve_with_particles(job, ParticleSet{}, options);
    SCOPED_TRACE("phi=" + std::to_string(k.phi));
    ASSERT_EQ(r.status, SolveStatus::kConverged) << r.reason;
    ASSERT_TRUE(r.dp_star.has_value());
    const double dy = (job.case_spec.probes.y2_dp - job.case_spec.probes.y1_dp) * job.case_spec.particle_diameter_cm;
    const double head = -g_y * dy / (k.u0 * k.u0);
    const double exact = exact_dp_star(job, k.phi, k.u0) + head;
    EXPECT_NEAR(*r.dp_star / exact, 1.0, 1e-4) << "dp_star " << *r.dp_star << " exact " << exact;
    if (k.phi == 0.0) {
      EXPECT_NEAR(exact, 1.962, 1e-12);  // 981 · 0.8 cm / (20 cm/s)²
    }
  }
}

TEST(UniformBed, EmptyDomainIsPlugFlowWithNoPressureDrop) {
  JobSpec job = uniform_bed(0.0, 20.0, DragLaw::kBvk);
  SolveOptions options;
  options.cold_start = true;
  const JobResult r = solve_with_particles(job, ParticleSet{}, options);
  ASSERT_EQ(r.status, SolveStatus::kConverged) << r.reason;
  ASSERT_TRUE(r.dp_star.has_value());
  // Plug flow u = U0 has zero gradients: no viscous stress, no convection
  // change, hence no pressure difference beyond round-off of the solve.
  EXPECT_NEAR(*r.dp_star, 0.0, 1e-6);
  EXPECT_LT(r.mass_imbalance, 1e-9);
}

}  // namespace
}  // namespace gridfree
