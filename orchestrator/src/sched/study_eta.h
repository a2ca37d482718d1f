// SPDX-License-Identifier: GPL-3.0-or-later
// Time left in a study from the plan's cost model (study/study_plan.h)
// scaled by the times measured so far:
//
//   s     = Σ_done wall_i / Σ_done model_i          (1 when nothing is done yet)
//   left  = Σ_queued s·model_j + Σ_running max(0, s·model_k − elapsed_k)
//   ETA   = left / max(1, workers)
//
// model_i is the cost model's estimate of job i (one thread); s absorbs the
// machine, the threads and the load. Pure functions, no I/O.
//
// That prices the workers only. A run also spends time between and around
// them — the orchestrator's own work per job (claims, records, series
// extrapolations, reports), worker start-up, slots left idle — which with
// short jobs or a large study is most of it. with_run_overhead adds it from
// this run's measured pace:
//
//   g     = max(0, elapsed − Σ_run wall_i / workers) / n_run
//   ETA'  = ETA + g · jobs_left
//
// elapsed = wall time since this run's first start, n_run and Σ_run wall_i
// the jobs this run finished and their workers' wall times; g is the wall
// time per job the workers do not explain. Used once n_run ≥
// kMinRunJobsForOverhead (before that: ETA).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct EtaJob {
  double model_s = 0;               // cost-model estimate
  enum class State { kQueued, kRunning, kDone } state = State::kQueued;
  double wall_s = 0;                // measured (done)
  double elapsed_s = 0;             // so far (running)
};

struct Eta {
  double scale = 1;                 // s above
  double seconds_left = 0;          // before dividing by the workers
  double eta_s = 0;                 // left / workers
};

Eta estimate_eta(const std::vector<EtaJob>& jobs, int workers);

// What this run measured so far (see with_run_overhead above).
struct RunPace {
  double elapsed_s = 0;    // since the run's first job started
  int finished = 0;        // jobs this run finished (final results)
  double worker_s = 0;     // Σ their workers' wall time
};

inline constexpr int kMinRunJobsForOverhead = 5;

// ETA' = eta_s + g · jobs_left (g from `pace`, see above).
double with_run_overhead(double eta_s, const RunPace& pace, int jobs_left, int workers);

// "2 h 05 min", "7 min", "< 1 min".
std::string hours_minutes(double seconds);

}  // namespace gridfree
