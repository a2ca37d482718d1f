// SPDX-License-Identifier: GPL-3.0-or-later
// What a finished job means for the store (failure classification):
//
//   exit 0 + valid converged result      → final: converged
//   exit 3 + result file                 → final: its status (not_converged | diverged | invalid | failed) + reason
//   exit 2                               → final: invalid (not retried: the input is wrong)
//   exit 1, other codes, a signal, a timeout,
//   a missing or garbage result file     → retryable (one more attempt, then failed)
//   exit 130 with a checkpoint written
//   during this attempt (our timeout,
//   Slurm pre-emption, a SIGTERM from
//   outside)                             → released (the next attempt resumes from it)
//   killed by our own shutdown, or gone
//   without a trace while nobody watched → released (queued again, attempt not spent)
//   refused by the cluster (bad partition,
//   a limit the job exceeds)             → final: failed, with the cluster's words
#pragma once

#include <filesystem>
#include <string>

#include "exec/executor.h"
#include "store/store.h"

namespace gridfree {

enum class OutcomeKind { kFinal, kRetryable, kReleased };

struct JobOutcome {
  OutcomeKind kind = OutcomeKind::kRetryable;
  ResultRow row;
};

// Reads <run_dir>/result.json (docs/INTERFACE.md §2). Throws std::runtime_error
// with the reason when it is missing or not a valid result document.
ResultRow read_result_file(const std::filesystem::path& file);

JobOutcome classify_exit(const JobExit& exit);

}  // namespace gridfree
