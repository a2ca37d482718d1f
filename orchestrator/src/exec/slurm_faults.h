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
#include <vector>

namespace gridfree {

enum class SubmitFault { kTransient, kPermanent };

// Classifies a failed sbatch from its exit code and stderr; `not_found`
// when sbatch itself could not be run.
SubmitFault classify_submit_failure(int exit_code, const std::string& stderr_text, bool not_found);

// sbatch's stderr reduced to one line for a message: its first
// kSubmitMessageLines non-empty lines joined by " | " ("" -> "exit N").
inline constexpr int kSubmitMessageLines = 5;
std::string submit_message(int exit_code, const std::string& stderr_text);

// The words of a command as one line a user can paste into a shell (words
// with characters the shell would read quoted).
std::string command_text(const std::vector<std::string>& words);

// What a permanently refused submission tells the user: sbatch's own words
// (submit_message), the command that was refused, and that nothing was
// spent ("sbatch refused the submission (exit 1): sbatch: error: invalid
// partition name specified; refused command: sbatch --parsable ...; no job
// started, no attempt or core-hour spent").
std::string refused_submission_message(int exit_code, const std::string& stderr_text,
                                       const std::vector<std::string>& command);

// True when a pending job's Reason (squeue %r) means it can never start.
bool never_startable(const std::string& reason);

// True when squeue/scancel failed because the controller did not answer
// (as opposed to a bad request).
bool controller_unreachable(const std::string& stderr_text);

}  // namespace gridfree
