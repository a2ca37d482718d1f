// SPDX-License-Identifier: GPL-3.0-or-later
// The scheduler loop (ninja's, in spirit):
//
//   1. while the budget allows (sched/budget.h: -j jobs, the memory budget,
//      largest first, bounded backfill): claim that job, write its run
//      directory, start it;
//   2. wait for one job to finish;
//   3. classify its exit (outcome.h) and record it in one transaction;
//      when that completes a series: extrapolate, store, rewrite the report.
//
// `run` works one study until it has no queued or running job; `daemon`
// works every active study in submission order until stopped. On a stop
// request in-flight jobs are killed and released (queued again, attempt not
// spent), so a restart picks them up.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "exec/executor.h"
#include "report/extrapolation_memo.h"
#include "sched/progress.h"
#include "store/store.h"

namespace gridfree {

struct SchedulerOptions {
  std::optional<long long> study;   // run: this study only; daemon: nullopt (all)
  int workers = 1;                  // jobs at once (-j)
  int threads_per_job = 1;          // --threads of each worker (cores / j, at least 1)
  // The pool's cores (local): a job starts only when the cores of the
  // running jobs plus its own fit (sched/budget.h), and a study's cores
  // rule (study/job_cores.h) is capped by them; 0 = not counted (Slurm,
  // where the rule is capped by threads_per_job, the --cpus-per-task).
  int cores = 0;
  // Memory budget (sched/budget.h): a job starts only when the estimates of
  // the running jobs plus its own fit; 0 = none (Slurm places the jobs).
  double memory_budget_bytes = 0;
  double timeout_s = -1;            // per job; 0 = none, < 0 = default_job_timeout_s (sched/job_timeout.h)
  int max_attempts = 2;             // a retryable failure is tried once more
  bool stop_when_idle = true;       // run: yes; daemon: no (poll for new work)
  double idle_poll_s = 1.0;
  std::filesystem::path runs_root;  // <db>.runs
  std::string owner;                // claim owner (this_process_owner())
  // Where a study's report goes (empty path = no report). Reports are
  // rewritten as series finish, paced (sched/report_pacer.h); `run` (a
  // study, stop_when_idle) writes the final one itself, after the loop.
  std::function<std::filesystem::path(const std::string& study_name)> report_dir;
  std::function<bool()> stop_requested = [] { return false; };
  Progress* progress = nullptr;
};

struct SchedulerSummary {
  int finished = 0;     // jobs with a final result recorded
  int converged = 0;
  int failed = 0;       // final, not converged
  int retried = 0;
  int series_finished = 0;
  bool interrupted = false;
  int reports_failed = 0;  // report writes that failed (logged)
  int requeued = 0;        // running jobs stopped and requeued on a stop request
  // A report was written after the last job outcome this loop recorded (and
  // nothing was requeued since): `run` need not write its final one again.
  bool reports_current = false;
};

// Startup recovery: requeues running jobs whose owner process is gone and
// kills their orphaned workers (if still alive). Returns the number requeued.
int recover_stale_jobs(Store& store);

// `adopted`: jobs already running in `executor` (adopt_stale_jobs), watched
// to the end like the ones this loop starts.
SchedulerSummary run_scheduler(Store& store, Executor& executor, const SchedulerOptions& options,
                               const std::vector<ClaimedJob>& adopted = {});

// Rewrites the report of a study. A failure is logged and returned as false
// (the results are safe in the store either way; `run` and `daemon` then
// exit non-zero). Once a stop is requested (options.stop_requested, also
// polled while the report is written: report/report_stop.h) the report is
// left for the next run and true returned. `memo`: the study's
// extrapolations of earlier writes (report/extrapolation_memo.h), if kept.
bool refresh_report(Store& store, long long study_id, const SchedulerOptions& options,
                    ExtrapolationMemo* memo = nullptr);

}  // namespace gridfree
