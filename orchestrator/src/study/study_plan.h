// Resource estimates for planning and validation: memory and run time of a
// job from its cell count. The constants are the one place to tune them.
//
//   memory(N) = kBytesPerCell · N + kBaseBytes
//   time(N)   = kIterationsEstimate(N) · N · kSecondsPerCellIteration / threads
//   iterations(N) ≈ kBaseIterations + kIterationsPerCellRoot · N^(1/3)
//   (SIMPLE-type outer iterations grow roughly with the cells along a line)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study.h"

namespace gridfree {

// Cost model, fitted to the bursting-bubble baseline (docs/BENCHMARKS.md):
// peak RSS 10.9 MB at 7.5 k cells and 42 MB at 60 k cells → ≈ 600 B/cell
// plus a few MB (the base below is kept generous); SIMPLEC iterations 66,
// 104, 212 at 1.6 k, 7.5 k, 60 k cells ≈ 5.5·N^(1/3); 1.9–2.4 µs of CPU per
// cell and iteration.
inline constexpr double kBytesPerCell = 600.0;
inline constexpr double kBaseBytes = 64.0 * 1024 * 1024;  // executable, particles, buffers
inline constexpr double kBaseIterations = 0.0;
inline constexpr double kIterationsPerCellRoot = 5.5;
inline constexpr double kSecondsPerCellIteration = 2.0e-6;  // one core

std::uint64_t physical_memory_bytes();  // sysconf(_SC_PHYS_PAGES) · page size
double estimated_memory_bytes(const std::array<int, 3>& cells);
double estimated_iterations(const std::array<int, 3>& cells);
double estimated_seconds(const std::array<int, 3>& cells, int threads);

struct PlanRow {
  std::string series;            // label
  std::size_t grids = 0;
  std::uint64_t cells = 0;       // summed over the series' grids
  std::uint64_t largest_cells = 0;
  double memory_bytes = 0;       // of the largest grid
  double seconds = 0;            // summed over grids (one worker)
};

struct Plan {
  std::vector<PlanRow> rows;
  std::size_t jobs = 0;
  std::uint64_t cells = 0;
  double max_memory_bytes = 0;
  double seconds = 0;            // serial total
  int workers = 1;
  double wall_seconds = 0;       // seconds / workers (perfect packing, a lower bound)
};

Plan make_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores);
nlohmann::json plan_to_json(const Plan& plan);
std::string plan_to_table(const Plan& plan);
std::string human_bytes(double bytes);
std::string human_seconds(double seconds);

}  // namespace gridfree
