// SPDX-License-Identifier: GPL-3.0-or-later
// One batched look at the queue: `squeue --me -h -o %i|%T|%r|%M` lists
// every job and array task of this user that has started, one line each,
// and the pending tasks of an array on one line, their indices in brackets:
//
//   1234_7|RUNNING|None|1:02
//   1234_[8-99,101%8]|PENDING|JobArrayTaskLimit|0:00
//
// So the output (and squeue's own work) grows with the tasks running and
// the arrays submitted, not with the tasks waiting: one line, not a
// thousand, for an array waiting behind its %N throttle.
//
// Asking for the user's jobs instead of `-j ID,...` keeps one purged id from
// failing the whole query (squeue exits 1 "Invalid job id specified").
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace gridfree {

struct QueueEntry {
  std::string state;      // PENDING, RUNNING, COMPLETING, ...
  std::string reason;     // why it pends ("None" when running)
  double used_s = 0;      // run time so far (TimeUsed)
};

// squeue's output; malformed lines are skipped.
class QueueListing {
 public:
  // The entry of job or array task `id` ("1234", "1234_7"): its own line,
  // or the combined line of its array's tasks that contains its index;
  // nullptr when squeue did not list it.
  const QueueEntry* find(const std::string& id) const;
  std::size_t lines() const { return lines_; }

 private:
  friend QueueListing parse_squeue(const std::string& text);
  struct Range {
    long first = 0, last = 0;
    std::size_t entry = 0;  // index into combined_
  };
  std::unordered_map<std::string, QueueEntry> single_;   // by id
  std::vector<QueueEntry> combined_;                      // one per combined line
  std::unordered_map<std::string, std::vector<Range>> ranges_;  // by array id
  std::size_t lines_ = 0;
};

QueueListing parse_squeue(const std::string& text);

// Slurm's duration "[days-][hours:]minutes:seconds" in seconds; nullopt if
// malformed ("INVALID", "UNLIMITED" ...).
std::optional<double> parse_slurm_duration(const std::string& text);

// The argv of that squeue call.
std::vector<std::string> squeue_command();

}  // namespace gridfree
