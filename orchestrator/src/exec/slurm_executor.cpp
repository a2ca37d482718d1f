// SlurmExecutor (see slurm_executor.h).
#include "exec/slurm_executor.h"

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

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

std::pair<int, std::string> run_capture(const std::string& command) {
  std::string out;
  FILE* p = popen((command + " 2>/dev/null").c_str(), "r");
  if (p == nullptr) return {-1, out};
  char buf[512];
  while (std::fgets(buf, sizeof buf, p) != nullptr) out += buf;
  const int status = pclose(p);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

std::string sbatch_script(const std::filesystem::path& worker, const JobLaunch& job) {
  std::ostringstream s;
  const auto dir = job.run_dir.string();
  s << "#!/bin/sh\n"
    << "#SBATCH --job-name=gridfree-" << job.job_hash.substr(0, 12) << "\n"
    << "#SBATCH --output=" << dir << "/worker.log\n"
    << "#SBATCH --cpus-per-task=" << std::max(1, job.threads) << "\n";
  if (job.timeout_s > 0) s << "#SBATCH --time=" << static_cast<long>(std::ceil(job.timeout_s / 60.0)) << "\n";
  std::string cmd;
  for (const auto& a : worker_command(worker, job.run_dir, job.threads)) cmd += (cmd.empty() ? "" : " ") + shell_quote(a);
  s << cmd << "\n"
    << "code=$?\n"
    << "echo $code > " << shell_quote(dir + "/exit_code.tmp") << " && mv " << shell_quote(dir + "/exit_code.tmp")
    << " " << shell_quote(dir + "/exit_code") << "\n"
    << "exit $code\n";
  return s.str();
}

SlurmExecutor::SlurmExecutor(std::filesystem::path worker, std::filesystem::path runs_root, double poll_interval_s)
    : worker_(std::move(worker)), runs_root_(std::move(runs_root)), poll_interval_s_(poll_interval_s) {}

SlurmExecutor::~SlurmExecutor() { kill_all(); }

void SlurmExecutor::start(const JobLaunch& job) {
  const auto script = job.run_dir / "job.sbatch";
  std::filesystem::remove(job.run_dir / "exit_code");
  {
    std::ofstream out(script, std::ios::trunc);
    out << sbatch_script(worker_, job);
  }
  const auto [rc, text] = run_capture("sbatch --parsable " + shell_quote(script.string()));
  std::string id = text.substr(0, text.find_first_of(";\n"));
  if (rc != 0 || id.empty()) {
    JobExit e;
    e.job_id = job.job_id;
    e.how = JobExit::How::kLaunchFailed;
    e.detail = "sbatch failed (exit " + std::to_string(rc) + ")";
    e.run_dir = job.run_dir;
    finished_.push_back(std::move(e));
    return;
  }
  jobs_[job.job_id] = SlurmJob{job.job_id, id, job.run_dir, Clock::now(), job.timeout_s};
}

std::string SlurmExecutor::external_id(long long job_id) const {
  auto it = jobs_.find(job_id);
  return it == jobs_.end() ? "" : "slurm:" + it->second.slurm_id;
}

JobExit SlurmExecutor::exit_of(const SlurmJob& j, bool timed_out) {
  JobExit e;
  e.job_id = j.job_id;
  e.run_dir = j.run_dir;
  e.wall_s = std::chrono::duration<double>(Clock::now() - j.started).count();
  if (timed_out) {
    e.how = JobExit::How::kTimedOut;
    e.detail = "no result after " + std::to_string(static_cast<long>(j.timeout_s)) + " s (scancel)";
    return e;
  }
  std::ifstream code_file(j.run_dir / "exit_code");
  int code = 0;
  if (code_file >> code) {
    e.how = JobExit::How::kExited;
    e.code = code;
    return e;
  }
  // The script never got to write its exit code: ask the accounting.
  const auto [rc, text] = run_capture("sacct -n -P -o State,ExitCode -j " + shell_quote(j.slurm_id));
  std::string line = text.substr(0, text.find('\n'));
  const auto bar = line.find('|');
  if (rc != 0 || bar == std::string::npos) {
    e.how = JobExit::How::kLost;
    e.detail = "slurm job " + j.slurm_id + " left the queue without an exit code";
    return e;
  }
  const std::string state = line.substr(0, bar), exit = line.substr(bar + 1);
  const auto colon = exit.find(':');
  const int signal = colon == std::string::npos ? 0 : std::atoi(exit.c_str() + colon + 1);
  if (state.rfind("TIMEOUT", 0) == 0) {
    e.how = JobExit::How::kTimedOut;
    e.detail = "slurm " + state;
  } else if (signal != 0) {
    e.how = JobExit::How::kSignaled;
    e.signal = signal;
  } else if (state.rfind("COMPLETED", 0) == 0 || state.rfind("FAILED", 0) == 0) {
    e.how = JobExit::How::kExited;
    e.code = std::atoi(exit.c_str());
  } else {
    e.how = JobExit::How::kLost;
    e.detail = "slurm state " + state;
  }
  return e;
}

void SlurmExecutor::poll() {
  if (jobs_.empty()) return;
  std::string ids;
  for (const auto& [id, j] : jobs_) ids += (ids.empty() ? "" : ",") + j.slurm_id;
  const auto [rc, text] = run_capture("squeue -h -o %i -j " + shell_quote(ids));
  if (rc != 0) return;  // squeue unavailable for a moment: try again later
  std::set<std::string> queued;
  std::istringstream in(text);
  for (std::string w; in >> w;) queued.insert(w);
  const auto now = Clock::now();
  for (auto it = jobs_.begin(); it != jobs_.end();) {
    const SlurmJob& j = it->second;
    const bool over = j.timeout_s > 0 && std::chrono::duration<double>(now - j.started).count() > j.timeout_s;
    if (queued.count(j.slurm_id) != 0 && !over) {
      ++it;
      continue;
    }
    if (queued.count(j.slurm_id) != 0) run_capture("scancel " + shell_quote(j.slurm_id));
    finished_.push_back(exit_of(j, queued.count(j.slurm_id) != 0));
    it = jobs_.erase(it);
  }
}

std::optional<JobExit> SlurmExecutor::wait_any(double timeout_s) {
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  for (;;) {
    if (!finished_.empty()) {
      JobExit e = std::move(finished_.front());
      finished_.erase(finished_.begin());
      return e;
    }
    if (std::chrono::duration<double>(Clock::now() - last_poll_).count() >= poll_interval_s_) {
      last_poll_ = Clock::now();
      poll();
      continue;
    }
    if (jobs_.empty() || Clock::now() >= until) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

std::vector<long long> SlurmExecutor::kill_all() {
  std::vector<long long> ids;
  for (const auto& [id, j] : jobs_) {
    run_capture("scancel " + shell_quote(j.slurm_id));
    ids.push_back(id);
  }
  jobs_.clear();
  for (const auto& e : finished_) ids.push_back(e.job_id);
  finished_.clear();
  return ids;
}

}  // namespace gridfree
