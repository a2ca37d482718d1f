// SPDX-License-Identifier: GPL-3.0-or-later
// Exit of a Slurm task that left the queue (see slurm_exit.h).
#include "exec/slurm_exit.h"

#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "exec/process_run.h"

namespace gridfree {

std::optional<int> read_exit_code(const std::filesystem::path& dir) {
  std::ifstream in(dir / "exit_code");
  int code = 0;
  if (in >> code) return code;
  return std::nullopt;
}

std::optional<JobExit> exit_from_sacct(const std::string& line, const JobExit& base) {
  const auto bar = line.find('|');
  if (bar == std::string::npos || bar == 0) return std::nullopt;
  JobExit e = base;
  const std::string state = line.substr(0, bar), exit = line.substr(bar + 1);
  const auto colon = exit.find(':');
  const int signal = colon == std::string::npos ? 0 : std::atoi(exit.c_str() + colon + 1);
  if (state.rfind("TIMEOUT", 0) == 0) {
    e.how = JobExit::How::kTimedOut;
    e.detail = "Slurm time limit (sacct " + state + ")";
  } else if (state.rfind("OUT_OF_ME", 0) == 0) {
    e.how = JobExit::How::kLost;
    e.detail = "Slurm memory limit (sacct OUT_OF_MEMORY)";
  } else if (signal != 0) {
    e.how = JobExit::How::kSignaled;
    e.signal = signal;
  } else if (state.rfind("COMPLETED", 0) == 0 || state.rfind("FAILED", 0) == 0) {
    e.how = JobExit::How::kExited;
    e.code = std::atoi(exit.c_str());
  } else {
    e.how = JobExit::How::kLost;
    e.detail = "Slurm state " + state;
  }
  return e;
}

std::optional<int> exit_code_from_result(const std::filesystem::path& result_json) {
  std::ifstream in(result_json);
  if (!in) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(in);
    if (!j.is_object() || !j.contains("status") || !j["status"].is_string()) return std::nullopt;
    return j["status"] == "converged" ? 0 : 3;  // the worker's own exit codes (docs/INTERFACE.md)
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

JobExit resolve_exit(const JobExit& base, const std::string& slurm_id, bool ended_unwatched) {
  JobExit e = base;
  if (auto code = read_exit_code(base.run_dir)) {
    e.how = JobExit::How::kExited;
    e.code = *code;
    return e;
  }
  const ProcessOutput acct = run_process({"sacct", "-n", "-P", "-X", "-o", "State,ExitCode", "-j", slurm_id});
  if (acct.exit_code == 0)
    if (auto from_acct = exit_from_sacct(acct.out.substr(0, acct.out.find('\n')), base)) return *from_acct;
  if (auto code = exit_code_from_result(base.run_dir / "result.json")) {
    e.how = JobExit::How::kExited;
    e.code = *code;
    return e;
  }
  e.detail = "slurm job " + slurm_id + " left the queue without an exit code or a result";
  e.how = ended_unwatched ? JobExit::How::kVanished : JobExit::How::kLost;
  return e;
}

}  // namespace gridfree
