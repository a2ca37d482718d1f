// SPDX-License-Identifier: GPL-3.0-or-later
// The whole frozen-bed solve of one job on one grid:
//   1. grid from the case and numerics.grid
//   2. particles (generator, file) or a uniform continuum bed
//   3. ε_s by deposition (centroid fails on cells with ε_s ≥ 1)
//   4. warm start, SIMPLEC outer iterations with the drag field updated
//      from the particles (coupling/)
//   5. dp_star probes, diagnostics, timing, peak memory, status and reason.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

#include "flow/simple_loop.h"
#include "job/job_spec.h"
#include "job/result.h"
#include "particles/particle.h"

namespace gridfree {

struct SolveOptions {
  std::optional<std::filesystem::path> vtk_dir;  // write the final fields here
  SimpleSettings simple;                         // relaxation and inner tolerances
  bool cold_start = false;                       // u = 0, p = 0 instead of the warm start
  // Start from the converged solution on a grid with half the cells per
  // axis, itself started the same way (docs/SOLVER.md, "Nested start");
  // off with cold_start.
  bool nested_start = true;
  std::size_t nested_min_cells = 5000;  // no nested start below this many cells (docs/SOLVER.md)
  // A coarse level that has not converged after this many outer iterations
  // (or the job's max_iterations, if fewer) stops; unless its residuals are
  // within 10× the steady tolerance, the grid above it starts from the
  // analytic warm start (docs/SOLVER.md, "Nested start").
  int nested_max_iterations = 1000;
  // A coarse level also stops when its residual has stalled for this many
  // outer iterations (flow/stall_monitor.h); its solution is still used when
  // within 10× the steady tolerance (docs/SOLVER.md, "Nested start").
  int nested_stall_window = 100;
  // Called after every outer iteration (progress output).
  IterationCallback on_iteration;
  // Stop and resume (flow/checkpoint.h, docs/INTERFACE.md §2). Polled after
  // every outer iteration; when it returns true the solve writes its state
  // to checkpoint_file (if set) and throws SolveStopped. A stop during the
  // nested start's coarse solve writes no checkpoint.
  std::function<bool()> stop_requested;
  std::optional<std::filesystem::path> checkpoint_file;
  // Generated beds are read from and stored in this folder (job/bed_cache.h).
  std::optional<std::filesystem::path> bed_cache;
  // Continue from this checkpoint: a missing file means start from zero; a
  // file that is not this job's (hash, grid) or is corrupt is ignored with a
  // warning, never partly used.
  std::optional<std::filesystem::path> resume_file;
};

// Thrown by solve_job when SolveOptions::stop_requested ended the solve.
struct SolveStopped : std::runtime_error {
  SolveStopped(int iteration_, bool written) :
      std::runtime_error("stopped on request after iteration " + std::to_string(iteration_)),
      iteration(iteration_), checkpoint_written(written) {}
  int iteration = 0;
  bool checkpoint_written = false;
};

// SimpleSettings of a job: steady tolerance, inner tolerance, max_iterations
// and stall_window from the job, the rest from `base`.
SimpleSettings simple_settings_for(const NumericsSpec& numerics, const SimpleSettings& base);

// The grid of a case: cells from the job, lengths L* d, periodic flags.
Grid job_grid(const CaseSpec& case_spec, const std::array<int, 3>& cells);

// Loads the particles (particles/) and solves.
JobResult solve_job(const JobSpec& job, const SolveOptions& options);

// Solves with the given particles (ignored for a uniform source). Does not
// fill job_hash and version.
JobResult solve_with_particles(const JobSpec& job, const ParticleSet& particles,
                               const SolveOptions& options);

}  // namespace gridfree
