// SPDX-License-Identifier: GPL-3.0-or-later
// Slurm array scripts and sbatch command lines (see slurm_script.h).
#include "exec/slurm_script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "exec/executor.h"

namespace gridfree {

std::string shell_quote(const std::string& w) {
  std::string out = "'";
  for (char c : w) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

std::string slurm_job_name(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (out.size() >= 100) break;
    out += (c <= ' ' || c == '\'' || c == '"' || c == '\\' || c >= 127) ? '_' : static_cast<char>(c);
  }
  return out.empty() ? "gridfree" : out;
}

void apply_job_cores(SlurmArray& a, const JobLaunch& job) {
  if (job.cores <= 0) return;
  a.threads = job.cores;
  if (job.cores_are_tasks) {
    a.tasks = job.cores;
    a.cpus = 1;
  } else {
    a.tasks = 1;
    a.cpus = job.cores;
  }
}

bool same_array_shape(const SlurmArray& a, const SlurmArray& b) {
  return a.cpus == b.cpus && a.tasks == b.tasks && a.threads == b.threads && a.time_minutes == b.time_minutes &&
         a.mem_mb == b.mem_mb && a.stop_lead_s == b.stop_lead_s && a.bed_cache == b.bed_cache;
}

std::string array_script(const std::filesystem::path& worker, const SlurmArray& a,
                         const std::vector<std::string>& setup) {
  std::ostringstream s;
  s << "#!/bin/sh\n# gridfree: " << a.run_dirs.size() << " job(s), one per array task\n"
    << "case \"${SLURM_ARRAY_TASK_ID:-0}\" in\n";
  for (std::size_t i = 0; i < a.run_dirs.size(); ++i) s << "  " << i << ") dir=" << shell_quote(a.run_dirs[i].string()) << " ;;\n";
  s << "  *) echo \"gridfree: no run folder for array task $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\nesac\n";
  for (const auto& line : setup) s << line << "\n";
  // The worker command with the run folder left to the shell variable.
  const auto cmd = worker_command(worker, "/RUN_DIR", a.threads, a.bed_cache);
  std::string line;
  for (const auto& w : cmd) {
    std::string word = shell_quote(w);
    const auto at = w.find("/RUN_DIR");
    if (at != std::string::npos) word = shell_quote(w.substr(0, at)) + "\"$dir\"" + shell_quote(w.substr(at + 8));
    line += (line.empty() ? "" : " ") + word;
  }
  // The worker runs in the background so that the shell can pass on the
  // SIGTERM Slurm sends it (--signal=B:TERM@..., pre-emption): the worker
  // then writes its checkpoint and exits 130. `wait` returns early when the
  // trap runs; the loop waits again until the worker itself has ended.
  s << line << " > \"$dir/worker.log\" 2>&1 &\n"
    << "pid=$!\n"
    << "stopped=0\n"
    << "trap 'stopped=1; kill -TERM $pid 2>/dev/null' TERM\n"
    << "wait $pid\n"
    << "code=$?\n"
    << "while [ $stopped = 1 ] && kill -0 $pid 2>/dev/null; do wait $pid; code=$?; done\n"
    << "echo $code > \"$dir/exit_code.tmp\" && mv \"$dir/exit_code.tmp\" \"$dir/exit_code\"\n"
    << "exit $code\n";
  return s.str();
}

std::string slurm_time_text(double minutes) {
  const long s = std::lround(minutes * 60);
  char buf[48];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string limits_note(const std::vector<SlurmArray>& arrays) {
  // Per source: the range of the values gridfree passes, or the value shown.
  struct Range {
    long lo = 0, hi = 0;
    std::string shown;
  };
  auto part = [&](const char* what, auto from, auto value, auto shown, auto text) {
    std::map<std::string, Range> by_source;
    std::vector<std::string> order;
    for (const auto& a : arrays) {
      const std::string src = from(a);
      if (src.empty()) continue;
      auto [it, added] = by_source.try_emplace(src);
      if (added) order.push_back(src);
      const long v = value(a);
      if (v > 0) {
        it->second.lo = it->second.lo == 0 ? v : std::min(it->second.lo, v);
        it->second.hi = std::max(it->second.hi, v);
      }
      if (!shown(a).empty()) it->second.shown = shown(a);
    }
    std::string out;
    for (const auto& src : order) {
      const Range& r = by_source[src];
      std::string v = r.shown;
      if (r.lo > 0) v = text(r.lo) + (r.hi > r.lo ? "-" + text(r.hi) : "");
      out += (out.empty() ? "" : ", ") + std::string(what) + (v.empty() ? "" : " " + v) + " " + src;
    }
    return out.empty() ? std::string(what) + " the cluster's default" : out;
  };
  const std::string time = part(
      "time limit", [](const SlurmArray& a) { return a.time_from; }, [](const SlurmArray& a) { return a.time_minutes; },
      [](const SlurmArray& a) { return a.time_shown; }, [](long m) { return slurm_time_text(static_cast<double>(m)); });
  const std::string mem = part(
      "memory", [](const SlurmArray& a) { return a.mem_from; }, [](const SlurmArray& a) { return a.mem_mb; },
      [](const SlurmArray& a) { return a.mem_shown; }, [](long mb) { return std::to_string(mb) + "M"; });
  return time + "; " + mem;
}

std::vector<std::string> sbatch_command(const SlurmArray& a, const SlurmSettings& s,
                                        const std::filesystem::path& script, const std::filesystem::path& log_dir) {
  std::vector<std::string> c = {"sbatch", "--parsable", "--job-name=" + slurm_job_name(a.name),
                                "--output=" + (log_dir / "%A_%a.out").string(),
                                "--cpus-per-task=" + std::to_string(a.cpus)};
  if (a.tasks > 1) c.push_back("--ntasks=" + std::to_string(a.tasks));
  std::string range = "--array=0-" + std::to_string(a.run_dirs.size() - 1);
  if (a.throttle > 0) range += "%" + std::to_string(a.throttle);
  c.push_back(range);
  if (a.time_minutes > 0) c.push_back("--time=" + std::to_string(a.time_minutes));
  if (a.mem_mb > 0) c.push_back("--mem=" + std::to_string(a.mem_mb) + "M");
  // SIGTERM to the batch shell this long before the time limit (the script
  // passes it to the worker, which checkpoints); no requeue by Slurm itself:
  // gridfree resubmits a stopped job, which resumes from its checkpoint.
  c.push_back("--signal=B:TERM@" + std::to_string(a.stop_lead_s));
  c.push_back("--no-requeue");
  if (!s.partition.empty()) c.push_back("--partition=" + s.partition);
  if (!s.account.empty()) c.push_back("--account=" + s.account);
  if (!s.qos.empty()) c.push_back("--qos=" + s.qos);
  if (!s.constraint.empty()) c.push_back("--constraint=" + s.constraint);
  for (const auto& x : s.sbatch_args) c.push_back(x);
  c.push_back(script.string());
  return c;
}

}  // namespace gridfree
