// SPDX-License-Identifier: GPL-3.0-or-later
// Every field of a job changes what is computed, as docs/INTERFACE.md §6
// says: the job of docs/INTERFACE.md §2 on a coarse grid (6 × 40 × 2 cells,
// Δ* = 5) is solved once as given and once per changed field, and the
// documented observable must move:
//   - physical fields, probes, grid, schemes, laws, filter: dp*;
//   - tolerances: the iterations (outer, inner or filter) spent — a
//     tighter tolerance must not spend fewer;
//   - max_iterations: the status (a cap below the need gives not_converged);
//   - the outlet pressure: nothing in dp* (only the level of p), checked as
//     an invariance.
// "Moves" means a relative change above 1e-9: the solves are deterministic
// (bitwise, any thread count), so an unchanged computation gives the same
// bits and any real change of the model shows far above round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contract_job.h"
#include "flow/solve.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

using nlohmann::json;

json coarse_job() {
  json j = test::contract_job();
  j["numerics"]["grid"] = {{"cells", {6, 40, 2}}};
  j["numerics"]["tolerances"] = {{"linear", 1e-2}, {"filter", 1e-10}, {"steady", 1e-5}};
  return j;
}

struct Outcome {
  std::string status;
  double dp = NAN;
  int iterations = 0;
  long inner = 0;         // momentum + pressure iterations
  long filter = 0;        // filter iterations (first deposition)
};

Outcome solve_outcome(const json& doc) {
  const JobSpec job = parse_job(doc, std::filesystem::current_path());
  SolveOptions opts;
  long inner = 0;
  opts.on_iteration = [&inner](const IterationReport& r) { inner += r.momentum_iterations + r.pressure_iterations; };
  const JobResult r = solve_job(job, opts);
  Outcome o;
  o.status = std::string(solve_status_name(r.status));
  o.dp = r.dp_star.value_or(NAN);
  o.iterations = r.iterations;
  o.inner = inner;
  if (r.extra.contains("filter") && r.extra["filter"].contains("iterations"))
    o.filter = r.extra["filter"]["iterations"].get<long>();
  return o;
}

const Outcome& baseline() {
  static const Outcome b = solve_outcome(coarse_job());
  return b;
}

bool moved(double a, double b) { return std::abs(a - b) > 1e-9 * std::abs(b); }

// Sets the field at `pointer` to `value` and expects dp* to move.
void expect_dp_moves(const std::string& pointer, const json& value) {
  json doc = coarse_job();
  doc[json::json_pointer(pointer)] = value;
  const Outcome o = solve_outcome(doc);
  ASSERT_EQ(baseline().status, "converged");
  EXPECT_EQ(o.status, "converged") << pointer;
  EXPECT_TRUE(moved(o.dp, baseline().dp)) << pointer << " = " << value.dump() << " left dp* at " << o.dp;
}

TEST(FieldEffect, CaseFieldsMoveDpStar) {
  expect_dp_moves("/case/domain_dp", {30, 160, 10});
  expect_dp_moves("/case/particle_diameter_cm", 0.012);
  expect_dp_moves("/case/gas/density_g_cm3", 2e-3);
  expect_dp_moves("/case/gas/viscosity_g_cm_s", 3e-4);
  expect_dp_moves("/case/gravity_cm_s2", {0, -981, 0});
  expect_dp_moves("/case/boundaries/x", "wall");
  expect_dp_moves("/case/boundaries/z", "wall");
  expect_dp_moves("/case/boundaries/y_low/superficial_velocity_cm_s", 25.0);
  expect_dp_moves("/case/particles/generator/seed", 2);
  expect_dp_moves("/case/particle_velocity/thermal_cm_s", 5.0);
  expect_dp_moves("/case/probes/pressure_drop/y1_dp", 10);
  expect_dp_moves("/case/probes/pressure_drop/y2_dp", 120);
}

TEST(FieldEffect, ParticleVelocitySeedMovesDpStarWhenParticlesMove) {
  json doc = coarse_job();
  doc["case"]["particle_velocity"] = {{"thermal_cm_s", 5.0}, {"seed", 0}};
  const Outcome a = solve_outcome(doc);
  doc["case"]["particle_velocity"]["seed"] = 1;
  const Outcome b = solve_outcome(doc);
  EXPECT_TRUE(moved(a.dp, b.dp)) << a.dp << " vs " << b.dp;
}

TEST(FieldEffect, NumericsFieldsMoveDpStar) {
  expect_dp_moves("/numerics/grid", {{"cells", {6, 50, 2}}});
  expect_dp_moves("/numerics/convection", "fou");
  expect_dp_moves("/numerics/drag", "hkl");
  expect_dp_moves("/numerics/deposition/fwhm_dp", 8);
  expect_dp_moves("/numerics/deposition/diffusivity", "mfix");
  expect_dp_moves("/numerics/deposition/integration", "gaussian");
  expect_dp_moves("/numerics/deposition", {{"kind", "centroid"}});
}

TEST(FieldEffect, OutletPressureOnlyShiftsThePressureLevel) {
  json doc = coarse_job();
  doc["case"]["boundaries"]["y_high"]["pressure_dyn_cm2"] = 1000.0;
  const Outcome o = solve_outcome(doc);
  // dp* is a difference of pressures: the level cancels up to round-off of
  // p ≈ 1000 dyn/cm² against differences of ≈ 400 (ρU0² dp*), so 1e-9.
  EXPECT_NEAR(o.dp, baseline().dp, 1e-9 * 1000.0 / (1e-3 * 400.0));
}

TEST(FieldEffect, TighterTolerancesSpendMoreIterations) {
  json doc = coarse_job();
  doc["numerics"]["tolerances"]["steady"] = 1e-7;
  const Outcome steady = solve_outcome(doc);
  EXPECT_GT(steady.iterations, baseline().iterations);

  doc = coarse_job();
  doc["numerics"]["tolerances"]["linear"] = 1e-6;
  const Outcome linear = solve_outcome(doc);
  EXPECT_EQ(linear.status, "converged");
  EXPECT_GT(linear.inner / std::max(1, linear.iterations), baseline().inner / std::max(1, baseline().iterations))
      << "inner iterations per outer iteration";

  // The filter tolerance bounds the linear solves of the backward-Euler
  // steps (the exact integration solves directly and has none). They need
  // several CG iterations per step only where the filter spreads over
  // several cells: a 20 d width on these 5 d cells.
  doc = coarse_job();
  doc["numerics"]["deposition"]["integration"] = "steps";
  doc["numerics"]["deposition"]["fwhm_dp"] = 20;
  const Outcome tight_filter = solve_outcome(doc);
  doc["numerics"]["tolerances"]["filter"] = 1e-4;
  const Outcome loose_filter = solve_outcome(doc);
  EXPECT_LT(loose_filter.filter, tight_filter.filter);
}

TEST(FieldEffect, IterationCapBelowTheNeedGivesNotConverged) {
  json doc = coarse_job();
  doc["numerics"]["max_iterations"] = 5;
  EXPECT_EQ(solve_outcome(doc).status, "not_converged");
}

}  // namespace
}  // namespace gridfree
