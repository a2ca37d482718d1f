// SPDX-License-Identifier: GPL-3.0-or-later
// Where the iterations fail, the result says so (issue "flow solver",
// docs/INTERFACE.md §2): a run stopped by max_iterations is `not_converged` with
// the residuals in its reason; a run that blows up is `diverged`, carries no
// dp_star and never a NaN. Failures are provoked with momentum
// over-relaxation (α_u > 1): α_u = 3 stalls with a steady dp* but an
// unsatisfied momentum balance, α_u = 6 blows up (measured on this bed;
// α_u = 1.9 still converges, drag-dominated beds are forgiving).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flow/solve.h"
#include "uniform_bed_job.h"

namespace gridfree {
namespace {

JobSpec bvk_bed() { return test_support::uniform_bed_job(0.3, 20.0, DragLaw::kBvk); }

TEST(HonestFailure, IterationCapGivesNotConvergedWithTheResidualsInTheReason) {
  JobSpec job = bvk_bed();
  job.numerics.max_iterations = 3;
  SolveOptions options;
  options.cold_start = true;
  const JobResult r = solve_with_particles(job, ParticleSet{}, options);
  EXPECT_EQ(r.status, SolveStatus::kNotConverged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_NE(r.reason.find("not converged after 3 iterations"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("continuity residual"), std::string::npos) << r.reason;
  EXPECT_GT(std::max(r.residual_continuity, r.residual_momentum), job.numerics.tolerances.steady);
}

TEST(HonestFailure, ASteadyPressureDropIsNotEnoughWhenMomentumIsUnbalanced) {
  JobSpec job = bvk_bed();
  job.numerics.max_iterations = 300;
  SolveOptions options;
  options.cold_start = true;
  options.simple.relax_u = 3.0;
  const JobResult r = solve_with_particles(job, ParticleSet{}, options);
  EXPECT_EQ(r.status, SolveStatus::kNotConverged) << r.reason;
  EXPECT_LT(r.dp_star_change, job.numerics.tolerances.steady);  // dp* stopped moving...
  EXPECT_GT(r.residual_momentum, 0.1);                          // ...at a wrong answer
  EXPECT_NE(r.reason.find("momentum residual"), std::string::npos) << r.reason;
}

TEST(HonestFailure, OverRelaxedIterationsAreReportedAsDivergedWithoutANumber) {
  JobSpec job = bvk_bed();
  SolveOptions options;
  options.cold_start = true;
  options.simple.relax_u = 6.0;
  int iterations_seen = 0;
  options.on_iteration = [&](const IterationReport&) { ++iterations_seen; };
  const JobResult r = solve_with_particles(job, ParticleSet{}, options);
  ASSERT_EQ(r.status, SolveStatus::kDiverged) << r.reason << " after " << r.iterations << " iterations";
  EXPECT_NE(r.reason.find("diverged at iteration"), std::string::npos) << r.reason;
  EXPECT_FALSE(r.dp_star.has_value());
  EXPECT_EQ(r.iterations, iterations_seen);
  EXPECT_LT(r.iterations, job.numerics.max_iterations);  // stopped early, not at the cap
}

TEST(HonestFailure, TheSameBedConvergesWithTheDefaultRelaxation) {
  // The control for the test above: only α_u differs.
  SolveOptions options;
  options.cold_start = true;
  const JobResult r = solve_with_particles(bvk_bed(), ParticleSet{}, options);
  EXPECT_EQ(r.status, SolveStatus::kConverged) << r.reason;
  ASSERT_TRUE(r.dp_star.has_value());
  EXPECT_TRUE(std::isfinite(*r.dp_star));
}

}  // namespace
}  // namespace gridfree
