// SPDX-License-Identifier: GPL-3.0-or-later
// Which queued job starts next on this machine: a memory and job-count
// budget (docs/ORCHESTRATOR.md, "Budgets").
//
//   need(job)  = the worker's estimate job_memory_estimate_bytes(cells)
//                (job/memory_estimate.h; the one model plan/validate use)
//   fits(job)  = in_use + need(job) ≤ budget, and cores_in_use + cores(job)
//                ≤ the pool's cores, or nothing runs (a job larger than the
//                budget, or needing more cores than the pool has, runs
//                alone, never beside another)
//   head       = the queued job with the largest need (ties: queue order)
//
// Rule (largest first where it fits, backfill with a bounded reservation):
//   1. running = max_jobs            → nothing starts
//   2. fits(head)                    → start head
//   3. the head has waited while max_head_skips smaller jobs were started
//      past it                       → nothing starts (the memory freed by
//                                      finishing jobs is kept for the head)
//   4. otherwise                     → start the largest job that fits
//      (a backfill; counts one skip of the head)
// Largest-first is the LPT rule, whose makespan is within 4/3 of the optimum
// for independent jobs on identical slots; the skip bound keeps a stream of
// small jobs from delaying the head indefinitely.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace gridfree {

struct QueuedJob {
  long long job_id = 0;
  double memory_bytes = 0;  // need(job)
  int cores = 1;            // cores(job) (study/job_cores.h)
};

struct BudgetUse {
  double memory_bytes = 0;  // sum of need over running jobs
  int jobs = 0;
  int cores = 0;            // sum of cores over running jobs
};

struct BudgetPolicy {
  double memory_budget_bytes = 0;  // 0 = no memory budget (e.g. Slurm places the jobs)
  int max_jobs = 1;                // -j
  int max_head_skips = 1;          // backfills allowed past a waiting head
  int cores = 0;                   // the pool's cores; 0 = not counted (Slurm places the jobs)
};

// What the rule remembers between calls: the head that waits and how many
// jobs were started past it.
struct HeadReservation {
  std::optional<long long> head;
  int skips = 0;
};

// Index into `queued` (any order) of the job to start now, or nullopt.
std::optional<std::size_t> pick_next_job(const std::vector<QueuedJob>& queued, const BudgetUse& in_use,
                                         const BudgetPolicy& policy, HeadReservation& reservation);

}  // namespace gridfree
