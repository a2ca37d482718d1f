// SPDX-License-Identifier: GPL-3.0-or-later
// SlurmExecutor (see slurm_executor.h).
#include "exec/slurm_executor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "exec/process_run.h"
#include "exec/slurm_exit.h"
#include "exec/slurm_faults.h"
#include "exec/slurm_queue.h"
#include "exec/worker_progress.h"
#include "study/slurm_block.h"
#include "study/external_plan.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

constexpr double kMinPollS = 0.5, kMaxPollS = 30.0;  // adaptive squeue interval bounds
constexpr double kFileCheckS = 0.1;                  // exit_code files of running tasks
constexpr double kMaxBackoffS = 60.0;                // transient submit faults
constexpr double kGatherS = 5.0;                     // a refill waits at most this long for more jobs
constexpr int kDefaultArraySize = 1000;              // SlurmSettings::array_size when unset

bool is_running(const std::string& state) { return state == "RUNNING" || state == "COMPLETING"; }

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <class Groups>
std::size_t unsent_count(const Groups& groups) {
  std::size_t n = 0;
  for (const auto& g : groups) n += g.second.size();
  return n;
}

std::string path_text() {
  const char* p = std::getenv("PATH");
  return p == nullptr ? "(unset)" : p;
}

// Rounds up to 1, 2, 4, 8 ...: limits within a factor 2 share an array.
long ladder(double v) {
  long r = 1;
  while (r < v) r *= 2;
  return r;
}

}  // namespace

SlurmExecutor::SlurmExecutor(std::filesystem::path worker, std::filesystem::path runs_root, SlurmSettings settings,
                             int slots)
    : worker_(std::move(worker)), runs_root_(std::move(runs_root)), settings_(std::move(settings)),
      slots_(std::max(1, slots)) {}

SlurmExecutor::~SlurmExecutor() { kill_all(); }

SlurmArray SlurmExecutor::shape_of(const JobLaunch& job) const {
  SlurmArray a;
  a.threads = std::max(1, job.threads);
  a.bed_cache = job.bed_cache;
  a.cpus = settings_.cpus_per_task.value_or(a.threads);
  apply_job_cores(a, job);  // a cores rule: the job's own --ntasks / --cpus-per-task
  a.throttle = slots_;
  const bool sized = job.cells[0] > 0 && job.cells[1] > 0 && job.cells[2] > 0;
  char margin_text[48];
  std::snprintf(margin_text, sizeof margin_text, "%g", settings_.margin);
  const std::string margin = std::string("computed from the cost model x ") + margin_text;
  // The user's own time limit wins (docs/ORCHESTRATOR.md "Time and memory"):
  // sbatch_args (after ours on sbatch's command line), the settings, then
  // SBATCH_TIMELIMIT, which sbatch reads only when gridfree passes no --time.
  const SbatchEnvironment& env = settings_.environment;
  std::optional<double> limit_minutes;  // the limit in effect, when known
  if (sbatch_words_set_time(settings_.sbatch_args)) {
    a.time_from = "from --sbatch-arg";
  } else if (settings_.time_minutes) {
    a.time_minutes = static_cast<long>(std::ceil(*settings_.time_minutes));
    a.time_from = "from the settings (--time / time_minutes)";
  } else if (env.time) {
    a.time_from = "from " + env.time->name;
    limit_minutes = slurm_time_minutes(env.time->value);
    a.time_shown = limit_minutes ? slurm_time_text(*limit_minutes) : env.time->value;
  } else if (job.timeout_s > 0) {  // Slurm's limit one minute past ours, so ours is the one that fires
    a.time_minutes = static_cast<long>(std::ceil(job.timeout_s / 60.0)) + 1;
    a.time_from = "from the job timeout + 1 min";
  } else if (job.own_estimate) {  // gridfree's model says nothing about another code's run time
    a.time_from =
        "not given, the cluster's default (external code without timeout_s, cost.cpu_s_per_cell or a finished job "
        "of the case: give --time or --timeout)";
  } else if (sized) {
    a.time_minutes = ladder(std::max(5.0, settings_.margin * estimated_seconds(job.cells, a.cpus) / 60.0));
    a.time_from = margin;
  }
  if (a.time_minutes > 0) limit_minutes = static_cast<double>(a.time_minutes);
  // An earlier attempt's progress file: its longest outer iteration widens
  // the lead (worker_progress.h), in whole minutes so that arrays still
  // form, and to at most half the time limit so the job still gets to work.
  double lead = std::ceil(stop_grace_for_run(job.run_dir, kSlurmStopLeadSeconds) / 60.0) * 60.0;
  if (limit_minutes) lead = std::min(lead, std::max<double>(kSlurmStopLeadSeconds, 30.0 * *limit_minutes));
  a.stop_lead_s = static_cast<int>(lead);
  if (sbatch_words_set_memory(settings_.sbatch_args)) {
    a.mem_from = "from --sbatch-arg";
  } else if (settings_.mem_mb) {
    a.mem_mb = static_cast<long>(std::ceil(*settings_.mem_mb));
    a.mem_from = "from the settings (--mem / mem_mb)";
  } else if (env.memory) {
    a.mem_from = "from " + env.memory->name;
    a.mem_shown = env.memory->value;
  } else if (job.own_estimate) {  // the scheduler's estimate (docs/EXTERNAL.md "Cost"), never gridfree's model
    if (std::isfinite(job.memory_bytes)) {
      a.mem_mb = ladder(settings_.margin * job.memory_bytes / (1024.0 * 1024.0));
      char safety[64];
      std::snprintf(safety, sizeof safety, "from the case's measured peak memory x %g x ", kExternalMemorySafety);
      a.mem_from =
          (job.memory_basis.rfind("declared", 0) == 0 ? std::string("from the declared cost.mb_per_cell x ") : safety) +
          margin_text;
    } else {
      a.mem_from = "not given, the cluster's default (external code, memory " +
                   (job.memory_basis.empty() ? std::string("unknown") : job.memory_basis) + ": give --mem or mem_mb)";
    }
  } else if (sized) {
    a.mem_mb = ladder(settings_.margin * estimated_memory_bytes(job.cells) / (1024.0 * 1024.0));
    a.mem_from = margin;
  }
  return a;
}

void SlurmExecutor::start(const JobLaunch& job) {
  std::filesystem::remove(job.run_dir / "exit_code");
  std::filesystem::remove(job.run_dir / "slurm_submit");
  if (unsent_.empty()) gathered_at_ = Clock::now();
  unsent_.push_back(job);
}

void SlurmExecutor::flush() {
  if (submit_due()) submit_unsent();
}

bool SlurmExecutor::submit_due() const {
  if (unsent_.empty() || fatal_ || Clock::now() < retry_at_) return false;
  // A job claimed as another one ends would otherwise be one sbatch (and one
  // array of one task) per job: it waits for others while enough of ours
  // wait in the queue already, up to a tenth of an array or kGatherS.
  const auto batch = std::max<std::size_t>(1, static_cast<std::size_t>(settings_.array_size.value_or(kDefaultArraySize)) / 10);
  if (unsent_.size() >= batch) return true;
  const auto waiting = static_cast<long>(tasks_.size()) - running_now_;
  if (waiting < 2L * slots_ + 8) return true;
  return seconds_since(gathered_at_) >= kGatherS;
}

void SlurmExecutor::submit_unsent() {
  // Group by shape, keeping the claim order inside each group.
  std::vector<std::pair<SlurmArray, std::vector<JobLaunch>>> groups;
  const auto max_size = static_cast<std::size_t>(settings_.array_size.value_or(kDefaultArraySize));
  for (const auto& job : unsent_) {
    const SlurmArray s = shape_of(job);
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) {
      return same_array_shape(x.first, s) && x.second.size() < max_size;
    });
    if (g == groups.end()) groups.push_back({s, {job}});
    else g->second.push_back(job);
  }
  unsent_.clear();
  std::vector<SlurmArray> shapes;
  for (const auto& g : groups) shapes.push_back(g.first);
  // Once per submission round: which limits applied and where from.
  std::string others;
  for (const auto& e : settings_.environment.others) others += "; " + e.name + "=" + e.value;
  spdlog::info("sbatch: {} job(s) in {} array(s): {}{}", unsent_count(groups), groups.size(), limits_note(shapes),
               others);
  for (std::size_t i = 0; i < groups.size(); ++i) {
    submit_group(groups[i].second, groups[i].first);
    if (!unsent_.empty()) {  // a fault: keep the rest for later (or for kill_all), in order
      for (std::size_t k = i + 1; k < groups.size(); ++k)
        unsent_.insert(unsent_.end(), groups[k].second.begin(), groups[k].second.end());
      return;
    }
  }
}

void SlurmExecutor::submit_group(const std::vector<JobLaunch>& group, const SlurmArray& shape) {
  SlurmArray a = shape;
  a.name = group.front().name + (group.size() > 1 ? " +" + std::to_string(group.size() - 1) : "");
  for (const auto& j : group) a.run_dirs.push_back(j.run_dir);
  const auto dir = runs_root_ / "slurm";
  std::filesystem::create_directories(dir);
  const auto script = dir / (group.front().job_hash.substr(0, 16) + "-" + std::to_string(getpid()) + "-" +
                             std::to_string(++array_counter_) + ".sbatch");
  {
    std::ofstream out(script, std::ios::trunc);
    out << array_script(worker_, a, settings_.setup);
    if (!out) throw std::runtime_error("cannot write " + script.string());
  }
  // Where each job went, before sbatch: a process killed between sbatch and
  // recording the id leaves this for the next one to find the job by.
  for (std::size_t i = 0; i < group.size(); ++i)
    std::ofstream(group[i].run_dir / "slurm_submit", std::ios::trunc) << script.string() << '\n' << i << '\n';
  const std::vector<std::string> command = sbatch_command(a, settings_, script, dir);
  const ProcessOutput r = run_process(command);
  const std::string id = r.out.substr(0, r.out.find_first_of(";\n"));
  const bool ok = r.exit_code == 0 && !id.empty() && id.find_first_not_of("0123456789") == std::string::npos;
  if (ok) {
    backoff_s_ = 0;
    for (std::size_t i = 0; i < group.size(); ++i) {
      Task t;
      t.launch = group[i];
      t.slurm_id = id + "_" + std::to_string(i);
      t.polled_at = Clock::now();
      note(t);
      tasks_.emplace(group[i].job_id, std::move(t));
    }
    return;
  }
  const std::string msg = submit_message(r.exit_code, r.err.empty() ? r.out : r.err);
  if (classify_submit_failure(r.exit_code, r.err, r.not_found) == SubmitFault::kTransient) {
    backoff_s_ = std::min(kMaxBackoffS, backoff_s_ == 0 ? 1.0 : 2 * backoff_s_);
    retry_at_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(backoff_s_));
    spdlog::warn("sbatch failed for now ({}); {} job(s) wait, retry in {:.0f} s", msg, group.size(), backoff_s_);
    unsent_.insert(unsent_.end(), group.begin(), group.end());
    return;
  }
  // Permanent: sbatch missing, a bad partition, account or option. No job is
  // to blame, so none spends an attempt: they stay unsent (kill_all hands
  // them back to be requeued) and nothing more is submitted.
  fatal_ = r.not_found ? "sbatch could not be run (" + msg + "); PATH=" + path_text()
                       : refused_submission_message(r.exit_code, r.err.empty() ? r.out : r.err, command);
  spdlog::error("{}; {} job(s) go back to the queue, no attempt spent", *fatal_, group.size());
  unsent_.insert(unsent_.end(), group.begin(), group.end());
}

std::optional<std::string> SlurmExecutor::find_unrecorded(const JobLaunch& job) {
  std::ifstream in(job.run_dir / "slurm_submit");
  std::string script, index;
  if (!std::getline(in, script) || !std::getline(in, index)) return std::nullopt;  // never submitted
  const ProcessOutput q = run_process({"squeue", "--me", "-h", "-r", "-o", "%i|%o"});
  std::istringstream lines(q.out);
  for (std::string line; std::getline(lines, line);) {
    const auto bar = line.find('|');
    if (bar == std::string::npos || line.substr(bar + 1) != script) continue;
    const std::string id = line.substr(0, bar);
    if (id.size() > index.size() + 1 && id.compare(id.size() - index.size() - 1, std::string::npos, "_" + index) == 0)
      return id;
  }
  // Not in the queue: it ran while nobody watched if it left its traces.
  if (read_exit_code(job.run_dir) || exit_code_from_result(job.run_dir / "result.json"))
    return "unrecorded";
  return std::nullopt;
}

bool SlurmExecutor::adopt(const JobLaunch& job, const std::string& given_id) {
  std::string external_id = given_id;
  if (external_id.empty()) {  // submitted (perhaps) but never recorded
    const auto found = find_unrecorded(job);
    if (!found) return false;
    external_id = "slurm:" + *found;
  }
  if (external_id.rfind("slurm:", 0) != 0 || external_id.size() <= 6) return false;
  Task t;
  t.launch = job;
  t.slurm_id = external_id.substr(6);
  t.adopted = true;
  t.state = "ADOPTED";
  t.polled_at = Clock::now();
  tasks_.emplace(job.job_id, std::move(t));
  last_poll_ = {};  // ask Slurm at once
  return true;
}

std::string SlurmExecutor::external_id(long long job_id) const {
  auto it = tasks_.find(job_id);
  return it == tasks_.end() ? "" : "slurm:" + it->second.slurm_id;
}

void SlurmExecutor::note(const Task& t) {
  updates_.push_back({t.launch.job_id, "slurm:" + t.slurm_id, t.state, t.reason});
}

std::vector<JobUpdate> SlurmExecutor::take_updates() {
  std::vector<JobUpdate> out;
  out.swap(updates_);
  return out;
}

double SlurmExecutor::poll_interval() const {
  if (settings_.poll_s) return *settings_.poll_s;
  // A quarter of the typical run time: short jobs are looked at often, hour-
  // long ones every 30 s. Before any has finished: the fastest bound.
  if (runs_seen_ == 0) return kMinPollS;
  return std::clamp(mean_run_s_ / 4, kMinPollS, kMaxPollS);
}

void SlurmExecutor::finish(std::map<long long, Task>::iterator it, JobExit e) {
  Task& t = it->second;
  if (e.how == JobExit::How::kExited && t.state == "RUNNING") {
    const double run_s = t.used_s + seconds_since(t.polled_at);
    mean_run_s_ = (mean_run_s_ * runs_seen_ + run_s) / (runs_seen_ + 1);
    ++runs_seen_;
  }
  if (is_running(t.state)) --running_now_;
  t.state = "ENDED";  // left the queue, or about to
  t.reason.clear();
  note(t);
  finished_.push_back(std::move(e));
  tasks_.erase(it);
}

JobExit SlurmExecutor::exit_of(const Task& t) {
  JobExit base;
  base.job_id = t.launch.job_id;
  base.run_dir = t.launch.run_dir;
  base.wall_s = t.used_s;
  // Adopted and never listed by squeue: it ended while no gridfree watched.
  return resolve_exit(base, t.slurm_id, t.adopted && !t.seen);
}

void SlurmExecutor::poll() {
  if (tasks_.empty()) return;
  const ProcessOutput r = run_process(squeue_command());
  if (r.exit_code != 0) {
    // Controller unreachable for a moment: nothing is known, nothing changes.
    spdlog::warn("squeue failed ({}); will ask again", submit_message(r.exit_code, r.err));
    return;
  }
  const QueueListing queue = parse_squeue(r.out);
  const auto now = Clock::now();
  for (auto it = tasks_.begin(); it != tasks_.end();) {
    Task& t = it->second;
    const QueueEntry* q = queue.find(t.slurm_id);
    if (q == nullptr) {  // left the queue (finished, cancelled, purged)
      auto next = std::next(it);
      finish(it, exit_of(t));
      it = next;
      continue;
    }
    const bool changed = q->state != t.state || q->reason != t.reason;
    if (changed) {
      running_now_ += static_cast<int>(is_running(q->state)) - static_cast<int>(is_running(t.state));
      t.state = q->state;
      t.reason = q->reason;
    }
    t.used_s = q->used_s;
    t.polled_at = now;
    t.seen = true;
    if (changed) note(t);
    if (t.state == "PENDING" && never_startable(t.reason)) {
      run_process({"scancel", t.slurm_id});
      JobExit e{t.launch.job_id, JobExit::How::kRefused, 0, 0,
                "Slurm will never start it (Reason=" + t.reason + ")", t.launch.run_dir, 0};
      auto next = std::next(it);
      finish(it, std::move(e));
      it = next;
      continue;
    }
    ++it;
  }
}

void SlurmExecutor::check_exit_files() {
  // Running tasks, and the first few not yet seen running (a short task can
  // start and end between two polls); the rest wait for squeue.
  const auto now = Clock::now();
  int unseen_budget = 2 * slots_ + 8;
  for (auto it = tasks_.begin(); it != tasks_.end();) {
    Task& t = it->second;
    auto next = std::next(it);
    const bool active = t.state == "RUNNING" || t.state == "COMPLETING" || t.state == "ADOPTED";
    if (!active && unseen_budget-- <= 0) {
      it = next;
      continue;
    }
    if (auto code = read_exit_code(t.launch.run_dir)) {
      JobExit e{t.launch.job_id, JobExit::How::kExited, *code, 0, "", t.launch.run_dir,
                t.used_s + std::chrono::duration<double>(now - t.polled_at).count()};
      finish(it, std::move(e));
    } else if (t.launch.timeout_s > 0 && t.state == "RUNNING" &&
               t.used_s + std::chrono::duration<double>(now - t.polled_at).count() > t.launch.timeout_s) {
      run_process({"scancel", t.slurm_id});
      JobExit e{t.launch.job_id, JobExit::How::kTimedOut, 0, 0,
                "ran " + std::to_string(static_cast<long>(t.launch.timeout_s)) + " s without a result (scancel)",
                t.launch.run_dir, t.launch.timeout_s};
      finish(it, std::move(e));
    }
    it = next;
  }
}

std::optional<JobExit> SlurmExecutor::wait_any(double timeout_s) {
  const auto until = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
  for (;;) {
    if (!finished_.empty()) {
      JobExit e = std::move(finished_.front());
      finished_.pop_front();
      return e;
    }
    if (fatal_) return std::nullopt;  // the caller stops (fatal_error())
    if (submit_due()) {
      submit_unsent();
      continue;
    }
    if (seconds_since(last_poll_) >= poll_interval()) {
      last_poll_ = Clock::now();
      poll();
      continue;
    }
    if (seconds_since(last_file_check_) >= kFileCheckS) {
      last_file_check_ = Clock::now();
      check_exit_files();
      if (!finished_.empty()) continue;
    }
    if ((tasks_.empty() && unsent_.empty()) || Clock::now() >= until) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::vector<long long> SlurmExecutor::kill_all() {
  std::vector<long long> ids;
  std::vector<std::string> cancel = {"scancel"};
  for (const auto& [id, t] : tasks_) {
    cancel.push_back(t.slurm_id);
    ids.push_back(id);
  }
  if (cancel.size() > 1) run_process(cancel);
  tasks_.clear();
  running_now_ = 0;
  for (const auto& j : unsent_) ids.push_back(j.job_id);
  unsent_.clear();
  for (const auto& e : finished_) ids.push_back(e.job_id);
  finished_.clear();
  return ids;
}

}  // namespace gridfree
