// SPDX-License-Identifier: GPL-3.0-or-later
// Resource estimates for planning and validation: memory and run time of a
// job from its cell count. The constants are the one place to tune them.
//
//   memory(N) = kWorkerBytesPerCell · N + kWorkerBaseBytes (job/memory_estimate.h)
//   time(N)   = r · iterations(N) · N · kSecondsPerCellIteration / threads
//   iterations(N) ≈ kBaseIterations + kIterationsPerCellRoot · N^(1/3)
//   (SIMPLE-type outer iterations grow roughly with the cells along a line)
//
// r is the job's cost ratio (study/cost_model.h): 1 for the bursting bubble
// the base model was fitted to, from finished similar jobs in the database
// or a-priori from the case's physics otherwise.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/cost_model.h"
#include "study/study.h"

namespace gridfree {

// Cost model, fitted to the bursting-bubble baseline (docs/BENCHMARKS.md).
// Memory: the worker's own estimate (job/memory_estimate.h).
// Grids below kNestedMinCells start from the analytic warm start: SIMPLEC
// iterations 41, 65 at 1.6 k, 7.5 k cells ≈ 20 + 2.65·N^(1/3) (solver/3,
// 2026-11-23; 1.7–1.8 µs of CPU per cell and iteration). Larger grids start
// from the solution on a grid with half the cells per axis (docs/SOLVER.md):
// the CPU time of the whole nested solve was 35 (60 k) and 30 (480 k)
// fine-grid iterations' worth (solver/4), and 20–23 at 8 k–60 k (solver/5),
// so kNestedIterations is used for them (an over-estimate now, on the
// safe side of the default timeout).
inline constexpr double kBaseIterations = 20.0;
inline constexpr double kIterationsPerCellRoot = 2.65;
inline constexpr double kNestedMinCells = 5000;            // the worker's nested-start threshold
inline constexpr double kNestedIterations = 35.0;
inline constexpr double kSecondsPerCellIteration = 1.8e-6;  // one core

std::uint64_t physical_memory_bytes();  // sysconf(_SC_PHYS_PAGES) · page size
double estimated_memory_bytes(const std::array<int, 3>& cells);
double estimated_iterations(const std::array<int, 3>& cells);
double base_cpu_seconds(double cells);  // r = 1, one thread
double estimated_seconds(const std::array<int, 3>& cells, int threads, double cost_ratio = 1);

struct PlanRow {
  std::string series;            // label
  std::size_t grids = 0;
  std::size_t alignment_jobs = 0;  // alignment-check variants (counted in cells, memory, seconds)
  std::uint64_t cells = 0;       // summed over the series' grids
  std::uint64_t largest_cells = 0;
  double memory_bytes = 0;       // of the largest grid
  double seconds = 0;            // summed over grids (one worker)
  CostSource cost_source = CostSource::kAPriori;  // history when every job's ratio came from it
  double cost_ratio_min = 0, cost_ratio_max = 0;  // r over the series' jobs
  std::string cost_basis;        // of the series' largest grid
  std::string memory_basis;      // external studies: where memory_bytes comes from (study/external_plan.h)
  std::string reads_jobs_of;     // external studies: another quantity of the same jobs, counted there
};

struct Plan {
  std::vector<PlanRow> rows;
  std::size_t jobs = 0;
  std::uint64_t cells = 0;
  double max_memory_bytes = 0;
  double seconds = 0;            // serial total
  int workers = 1;
  int threads_per_worker = 1;    // cores / workers, at least 1 (each worker's --threads)
  double wall_seconds = 0;       // seconds / workers (perfect packing, a lower bound)
  bool external = false;         // an external study's (study/external_plan.h): NaN = unknown
};

// `history`: finished jobs of a database (sched/cost_history.h), empty for
// the a-priori model alone. The kind's plan (study/case_kind.h).
Plan make_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
               const CostHistory& history = {});
// A particle-bed study's plan (gridfree's cost model); an external study's
// is study/external_plan.h's.
Plan make_particle_bed_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                            const CostHistory& history);
nlohmann::json plan_to_json(const Plan& plan);
std::string plan_to_table(const Plan& plan);
std::string human_bytes(double bytes);
std::string human_seconds(double seconds);

}  // namespace gridfree
