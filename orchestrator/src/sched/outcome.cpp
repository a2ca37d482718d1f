// SPDX-License-Identifier: GPL-3.0-or-later
// Failure classification of finished jobs (see outcome.h).
#include "sched/outcome.h"

#include <chrono>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/json_limits.h"

namespace gridfree {
namespace {

bool known_status(const std::string& s) {
  return s == "converged" || s == "not_converged" || s == "diverged" || s == "invalid" || s == "failed";
}

double number_at(const nlohmann::json& j, const char* a, const char* b = nullptr) {
  const nlohmann::json* p = &j;
  for (const char* k : {a, b}) {
    if (k == nullptr) break;
    if (!p->is_object() || !p->contains(k)) return 0;
    p = &(*p)[k];
  }
  return p->is_number() ? p->get<double>() : 0;
}

}  // namespace

ResultRow read_result_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("no result file");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = parse_json_text(text.str(), file.string());  // limits: core/json_limits.h
  } catch (const InputError& e) {
    throw std::runtime_error("result file is not valid JSON (" + format_problems(e.problems()) + ")");
  }
  if (!j.is_object() || !j.contains("status") || !j["status"].is_string())
    throw std::runtime_error("result file has no status");
  ResultRow r;
  r.status = j["status"].get<std::string>();
  if (!known_status(r.status)) throw std::runtime_error("result file has unknown status '" + r.status + "'");
  if (j.contains("reason") && j["reason"].is_string()) r.reason = j["reason"].get<std::string>();
  if (j.contains("srq") && j["srq"].is_object() && j["srq"].contains("dp_star") && j["srq"]["dp_star"].is_number()) {
    const double v = j["srq"]["dp_star"].get<double>();
    if (std::isfinite(v)) r.dp_star = v;
  }
  // An external job's result (docs/EXTERNAL.md) carries its quantities
  // instead of dp*; its series read them (store_query.cpp).
  const bool external = j.contains("quantities") && j["quantities"].is_object();
  if (external && r.status == "converged") {
    bool finite = false;
    for (const auto& [name, v] : j["quantities"].items()) finite = finite || (v.is_number() && std::isfinite(v.get<double>()));
    if (!finite) throw std::runtime_error("converged result without a finite quantity");
  }
  if (r.status == "converged" && !r.dp_star && !external)
    throw std::runtime_error("converged result without a finite srq.dp_star");
  if (j.contains("grid") && j["grid"].is_object()) {
    const auto& g = j["grid"];
    if (external) r.delta_star = number_at(g, "h");
    if (g.contains("cells") && g["cells"].is_array() && g["cells"].size() == 3)
      for (int a = 0; a < 3; ++a) r.cells[a] = g["cells"][a].is_number_integer() ? g["cells"][a].get<int>() : 0;
    if (!external) r.delta_star = number_at(g, "delta_star");
  }
  r.iterations = static_cast<int>(number_at(j, "iterations"));
  r.wall_s = number_at(j, "timing", "wall_s");
  r.cpu_s = number_at(j, "timing", "cpu_s");
  r.peak_rss_mb = number_at(j, "memory", "peak_rss_mb");
  r.result_json = j.dump();
  return r;
}

// True when the run folder holds a checkpoint written since this attempt
// started (its modification time within the attempt's wall time, 1 s slack
// for file-system time granularity).
static bool checkpoint_from_this_attempt(const JobExit& e) {
  std::error_code ec;
  const auto written = std::filesystem::last_write_time(checkpoint_file(e.run_dir), ec);
  if (ec) return false;
  const auto age = std::chrono::duration<double>(std::filesystem::file_time_type::clock::now() - written).count();
  return age <= e.wall_s + 1.0;
}

JobOutcome classify_exit(const JobExit& e) {
  JobOutcome out;
  const auto result_file = e.run_dir / "result.json";
  const auto log_tail = [&] {
    const std::string t = tail_of_file(e.run_dir / "worker.log", 3);
    return t.empty() ? std::string() : " [log: " + t + "]";
  };
  if (e.how == JobExit::How::kRefused) {  // the cluster will not run it: retrying cannot help
    out.kind = OutcomeKind::kFinal;
    out.row.status = "failed";
    out.row.reason = describe(e);
    return out;
  }
  if (e.how == JobExit::How::kKilled || e.how == JobExit::How::kVanished) {
    out.kind = OutcomeKind::kReleased;
    out.row.reason = describe(e);
    return out;
  }
  if (e.how == JobExit::How::kTimedOut && e.code == 130 && checkpoint_from_this_attempt(e)) {
    // Our timeout's SIGTERM, answered with a checkpoint: the work is kept and
    // the next attempt continues from it, so no attempt is spent. Each such
    // stop advances the checkpoint by at least one outer iteration, so a job
    // still ends, at the latest at numerics.max_iterations (or, for a limit
    // cycle, at its numerics.stall_window).
    out.kind = OutcomeKind::kReleased;
    out.row.reason = describe(e) + "; checkpoint kept, the next attempt resumes from it";
    return out;
  }
  if (e.how != JobExit::How::kExited) {
    out.kind = OutcomeKind::kRetryable;
    out.row.reason = describe(e) + log_tail();
    out.row.wall_s = e.wall_s;
    return out;
  }
  if (e.code == 0 || e.code == 3) {
    try {
      out.row = read_result_file(result_file);
    } catch (const std::exception& ex) {
      if (e.code == 3) {  // ran and said so, but left no readable result: final
        out.kind = OutcomeKind::kFinal;
        out.row.status = "failed";
        out.row.reason = std::string("exit 3 and ") + ex.what() + log_tail();
        return out;
      }
      out.kind = OutcomeKind::kRetryable;
      out.row.reason = std::string("exit 0 but ") + ex.what() + log_tail();
      return out;
    }
    if (e.code == 0 && out.row.status != "converged") {
      out.kind = OutcomeKind::kRetryable;
      out.row.reason = "exit 0 with result status '" + out.row.status + "'";
      return out;
    }
    if (e.code == 3 && out.row.status == "converged") {
      out.row.status = "failed";
      out.row.reason = "exit 3 with a converged result";
    }
    if (out.row.status != "converged" && out.row.reason.empty()) out.row.reason = "worker exit " + std::to_string(e.code);
    if (out.row.wall_s == 0) out.row.wall_s = e.wall_s;
    out.kind = OutcomeKind::kFinal;
    return out;
  }
  if (e.code == 2) {
    out.kind = OutcomeKind::kFinal;
    try {
      out.row = read_result_file(result_file);
    } catch (const std::exception&) {
    }
    out.row.status = "invalid";
    if (out.row.reason.empty()) out.row.reason = "worker rejected the job (exit 2)" + log_tail();
    return out;
  }
  if (e.code == 130 && checkpoint_from_this_attempt(e)) {  // stopped (pre-emption) with its work kept
    out.kind = OutcomeKind::kReleased;
    out.row.reason = "stopped by a signal; checkpoint kept, the next attempt resumes from it";
    return out;
  }
  out.kind = OutcomeKind::kRetryable;
  out.row.reason = "worker " + describe(e) + log_tail();
  out.row.wall_s = e.wall_s;
  return out;
}

}  // namespace gridfree
