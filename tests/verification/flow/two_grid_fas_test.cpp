// SPDX-License-Identifier: GPL-3.0-or-later
// The two-grid FAS prototype (flow/two_grid_fas.h) on the bursting-bubble
// baseline (PHYSICS.md §6: PC1, superbee, bvk, default transfer) at Δ* = 2
// (15 × 100 × 5 cells, coarse level 8 × 50 × 3): the coarse-grid
// correction with the τ sources must leave the fine grid's fixed point
// where it is. A τ without its coarse-residual term pulls the fine state
// towards the coarse solution, ≈ 1 % away, in every cycle, and the cycles
// do not converge; at this grid the correction does not reduce the fine
// sweeps (the speed is measured in bench/outer_bench, docs/DESIGN.md).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>

#include "flow/solve.h"
#include "particles/particle_io.h"
#include "bubble_baseline_job.h"

namespace gridfree {
namespace {

using test_support::bubble_fixed_point_job;

TEST(TwoGridFas, ReachesTheSimplecFixedPointWithinTheIterativeTolerance) {
  omp_set_num_threads(1);
  const ParticleSet set = load_particles(bubble_fixed_point_job(2.0, 1e-5).case_spec.particles,
                                         bubble_fixed_point_job(2.0, 1e-5).case_spec);
  SolveOptions options;
  options.nested_min_cells = 5000;  // a coarse level for the 7500-cell grid
  // Reference: plain SIMPLEC to a steady tolerance 1000× tighter.
  const JobResult ref = solve_with_particles(bubble_fixed_point_job(2.0, 1e-8), set, options);
  options.simple.fas_smoothing_sweeps = 4;
  options.simple.fas_coarse_sweeps = 10;
  const JobResult fas = solve_with_particles(bubble_fixed_point_job(2.0, 1e-5), set, options);
  ASSERT_EQ(ref.status, SolveStatus::kConverged) << ref.reason;
  ASSERT_EQ(fas.status, SolveStatus::kConverged) << fas.reason;
  ASSERT_TRUE(ref.dp_star && fas.dp_star);
  ASSERT_TRUE(fas.extra.contains("fas"));
  EXPECT_GE(fas.extra["fas"]["cycles"].get<int>(), 1);  // a coarse correction was applied
  const double error = std::abs(*fas.dp_star - *ref.dp_star) / *ref.dp_star;
  // FAS stops when dp* changed by < 1e-5 relative over a cycle with the
  // residuals below 1e-5: its distance to the fixed point is of that order.
  EXPECT_LT(error, 1e-5) << "FAS " << *fas.dp_star << " ref " << *ref.dp_star;
  std::printf("Δ* 2: reference %.10g (%d sweeps); FAS %.10g (%d fine sweeps, %d cycles, %d coarse sweeps), "
              "rel. error %.2e\n",
              *ref.dp_star, ref.iterations, *fas.dp_star, fas.iterations, fas.extra["fas"]["cycles"].get<int>(),
              fas.extra["fas"]["coarse_sweeps"].get<int>(), error);
}

}  // namespace
}  // namespace gridfree
