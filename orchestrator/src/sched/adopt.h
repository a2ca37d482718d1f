// SPDX-License-Identifier: GPL-3.0-or-later
// Adoption after a crash (docs/ORCHESTRATOR.md, "Adoption"): jobs a dead
// `run`/`daemon` left in an external queue (jobs.external_id "slurm:ID") are
// taken over by this process and handed to the executor, which asks the
// queue what became of them: pending or running ones are waited for,
// finished ones ingested, vanished ones run again. No job is submitted twice
// while its first submission lives, and no finished result is thrown away.
#pragma once

#include <string>
#include <vector>

#include "exec/executor.h"
#include "store/store.h"

namespace gridfree {

// Takes over the stale jobs `executor` can watch; the others stay for
// recover_stale_jobs (requeued). `timeout_s` (0 = none) applies to their run
// time as to new jobs. Returns the adopted jobs for run_scheduler.
std::vector<ClaimedJob> adopt_stale_jobs(Store& store, Executor& executor, const std::string& owner,
                                         double timeout_s = 0, const std::string& prefix = "slurm:");

}  // namespace gridfree
