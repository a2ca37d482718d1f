// SPDX-License-Identifier: GPL-3.0-or-later
// What a Slurm failure means for the job (docs/ORCHESTRATOR.md, "Slurm
// faults"). Pure functions of what Slurm said, so the rules are testable
// without a cluster:
//
//   sbatch refused a job  -> transient: retry the submission later, with
//                            backoff, without spending an attempt
//                            (controller unreachable, timeouts, submit limits)
//                         -> permanent: a configuration error (bad
//                            partition/account/QOS, bad options, script
//                            errors, sbatch missing): nothing more is
//                            submitted, the run stops with sbatch's own
//                            message, no attempt spent (fatal_error())
//   a job waits in the queue with a Reason that no waiting can change
//   (PartitionTimeLimit, ...PerJobLimit, InvalidAccount, ...) -> never
//   startable: cancel it and fail it with that reason.
#pragma once

#include <string>

namespace gridfree {

enum class SubmitFault { kTransient, kPermanent };

// Classifies a failed sbatch from its exit code and stderr; `not_found`
// when sbatch itself could not be run.
SubmitFault classify_submit_failure(int exit_code, const std::string& stderr_text, bool not_found);

// sbatch's stderr reduced to one line for a message ("" -> "exit N").
std::string submit_message(int exit_code, const std::string& stderr_text);

// True when a pending job's Reason (squeue %r) means it can never start.
bool never_startable(const std::string& reason);

// True when squeue/scancel failed because the controller did not answer
// (as opposed to a bad request).
bool controller_unreachable(const std::string& stderr_text);

}  // namespace gridfree
