// SPDX-License-Identifier: GPL-3.0-or-later
// Jobs no study needs any more (docs/ORCHESTRATOR.md "Unneeded jobs and
// gc"): a study replaced (--replace, or an external study whose template or
// code version changed) leaves the jobs only it linked without a study.
// They are kept, results and run folders included: a study that asks for
// them again (a reverted template edit) reuses them and reruns nothing,
// and the measured cost history keeps them. Only `gridfree gc` removes
// them, and `gridfree delete` the jobs of the study it deletes.
#pragma once

#include <string>
#include <vector>

#include "store/store.h"

namespace gridfree {

struct UnneededJob {
  long long id = 0;
  std::string hash, status, case_name;  // case_name from the job document ("" when it has none)
  long long cells = 0;
};

// Every job no study links, in id order.
std::vector<UnneededJob> unneeded_jobs(Database& db);

// Inside a transaction: those of `candidates` (job ids) that no study links
// now stay; a queued one is cancelled (nothing needs it run; a study that
// links it again queues it again). Their hashes.
std::vector<std::string> keep_unlinked_jobs(Database& db, const std::vector<long long>& candidates);

// Inside a transaction: those of `candidates` that no study links are
// removed with their results, uncertainties and events. Their hashes.
std::vector<std::string> remove_unlinked_jobs(Database& db, const std::vector<long long>& candidates);

// gridfree gc: removes every unneeded job in one transaction and records a
// 'gc' event. The removed jobs (their run folders can go too).
std::vector<UnneededJob> remove_unneeded_jobs(Store& store);

// Whether a job with this hash is in the database (gc leaves the run folder
// of a job a submit made again after it was removed).
bool job_hash_stored(Database& db, const std::string& hash);

}  // namespace gridfree
