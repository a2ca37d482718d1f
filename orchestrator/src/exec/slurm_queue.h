// One batched look at the queue: `squeue --me -h -r -o %i|%T|%r|%M` lists
// every job and array task of this user, one line each:
//
//   1234_7|RUNNING|None|1:02
//   1234_8|PENDING|JobArrayTaskLimit|0:00
//
// Asking for the user's jobs instead of `-j ID,...` keeps one purged id from
// failing the whole query (squeue exits 1 "Invalid job id specified").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct QueueEntry {
  std::string state;      // PENDING, RUNNING, COMPLETING, ...
  std::string reason;     // why it pends ("None" when running)
  double used_s = 0;      // run time so far (TimeUsed)
};

// squeue's output by job id; malformed lines are skipped.
std::map<std::string, QueueEntry> parse_squeue(const std::string& text);

// Slurm's duration "[days-][hours:]minutes:seconds" in seconds; nullopt if
// malformed ("INVALID", "UNLIMITED" ...).
std::optional<double> parse_slurm_duration(const std::string& text);

// The argv of that squeue call.
std::vector<std::string> squeue_command();

}  // namespace gridfree
