// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm fault classification (see slurm_faults.h). The phrases are Slurm
// 22.05's error strings (slurm_strerror) as sbatch and squeue print them.
#include "exec/slurm_faults.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace gridfree {
namespace {

bool contains_any(const std::string& text, std::initializer_list<std::string_view> phrases) {
  return std::any_of(phrases.begin(), phrases.end(),
                     [&](std::string_view p) { return text.find(p) != std::string::npos; });
}

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool controller_unreachable(const std::string& e) {
  return contains_any(e, {"Unable to contact slurm controller", "Socket timed out", "Connection refused",
                          "Connection timed out", "Zero Bytes were transmitted", "Communication connection failure",
                          "Slurmctld is not responding", "Resource temporarily unavailable",
                          "Transport endpoint is not connected", "Unable to establish controller machine",
                          "Insane message length", "Protocol authentication error", "Munge encode failed",
                          "Munge decode failed"});
}

SubmitFault classify_submit_failure(int exit_code, const std::string& e, bool not_found) {
  if (not_found) return SubmitFault::kPermanent;  // no sbatch on PATH: waiting will not help
  if (controller_unreachable(e)) return SubmitFault::kTransient;
  // Queue-size limits clear as jobs finish: the submission waits.
  if (contains_any(e, {"MaxSubmitJob", "MaxSubmit", "Slurm temporarily unable to accept job", "Job limit exceeded",
                       "job count limit", "MaxJobCount", "Too many jobs", "rate limit", "Slurm is busy",
                       "Slurmctld is busy", "try again"}))
    return SubmitFault::kTransient;
  // sbatch killed by a signal (exit -1) is not a verdict on the job.
  if (exit_code < 0) return SubmitFault::kTransient;
  return SubmitFault::kPermanent;
}

std::string submit_message(int exit_code, const std::string& e) {
  std::string msg;
  std::size_t start = 0;
  int lines = 0;
  while (start < e.size() && lines < kSubmitMessageLines) {
    auto end = e.find('\n', start);
    if (end == std::string::npos) end = e.size();
    std::string line = e.substr(start, end - start);
    start = end + 1;
    if (line.empty()) continue;
    msg += (msg.empty() ? "" : " | ") + line;
    ++lines;
  }
  if (msg.size() > 400) msg = msg.substr(0, 400) + "...";
  return msg.empty() ? "sbatch exit " + std::to_string(exit_code) : msg;
}

std::string command_text(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) {
    if (!out.empty()) out += ' ';
    const bool plain = !w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789-_=./:,@%+") == std::string::npos;
    if (plain) {
      out += w;
      continue;
    }
    out += '\'';
    for (char c : w) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    out += '\'';
  }
  return out;
}

std::string refused_submission_message(int exit_code, const std::string& e, const std::vector<std::string>& command) {
  return "sbatch refused the submission (exit " + std::to_string(exit_code) + "): " + submit_message(exit_code, e) +
         "; refused command: " + command_text(command) + "; no job started, no attempt or core-hour spent";
}

bool never_startable(const std::string& r) {
  static const std::array<std::string_view, 11> kNever = {
      "PartitionTimeLimit", "PartitionNodeLimit", "BadConstraints",  "InvalidAccount",
      "InvalidQOS",         "QOSMaxMemoryPerJob", "QOSMinCpuNotSatisfied", "QOSMinGRES",
      "AccountNotAllowed",  "QOSNotAllowed",      "PartitionMemLimit"};
  if (std::find(kNever.begin(), kNever.end(), r) != kNever.end()) return true;
  // The node could not launch it; Slurm holds it until an administrator acts.
  if (r == "launch failed requeued held") return true;
  // QOSMaxWallDurationPerJobLimit, QOSMaxCpuPerJobLimit, AssocMaxNodePerJobLimit ...:
  // a per-job limit the job itself exceeds; the per-user/per-account limits
  // (QOSMaxJobsPerUserLimit, AssocGrpCpuLimit ...) clear as other jobs end.
  return (r.rfind("QOSMax", 0) == 0 || r.rfind("AssocMax", 0) == 0) &&
         (ends_with(r, "PerJobLimit") || ends_with(r, "PerJob"));
}

}  // namespace gridfree
