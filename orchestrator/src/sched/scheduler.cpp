// SPDX-License-Identifier: GPL-3.0-or-later
// The scheduler loop (see scheduler.h).
#include "sched/scheduler.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <thread>

#include <spdlog/spdlog.h>

#include "exec/local_executor.h"
#include "job/memory_estimate.h"
#include "sched/budget_claim.h"
#include "sched/external_estimates.h"
#include "sched/external_result.h"
#include "sched/job_timeout.h"
#include "study/case_kind.h"
#include "study/cost_model.h"
#include "study/format_number.h"
#include "study/job_cores.h"
#include "study/study_plan.h"
#include "sched/outcome.h"
#include "sched/progress_tally.h"
#include "sched/report_pacer.h"
#include "sched/series_finish.h"
#include "sched/study_status.h"
#include "store/owner.h"

namespace gridfree {
namespace {

struct InFlight {
  ClaimedJob job;
  std::string label;
  double memory_bytes = 0;  // need(job), reserved while it runs (sched/budget.h)
  int cores = 1;            // cores(job), reserved while it runs
};

BudgetUse budget_use(const std::map<long long, InFlight>& running) {
  BudgetUse u;
  for (const auto& [id, f] : running) {
    u.memory_bytes += f.memory_bytes;
    u.cores += f.cores;
    ++u.jobs;
  }
  return u;
}

std::string job_label(Store& store, const ClaimedJob& job) {
  auto st = store.db().prepare(
      "SELECT se.case_name, se.convection, se.fwhm_dp, se.drag, se.deposition, sj.alignment_only FROM study_jobs sj "
      "JOIN series se ON se.id = sj.series_id WHERE sj.job_id = ? AND +sj.study_id = ? "
      "ORDER BY sj.alignment_only LIMIT 1");
  st.bind_all(job.job_id, job.study_id);
  std::string label = job.job_hash.substr(0, 12);
  if (st.step()) {
    SeriesKey k{st.as_text(0), st.as_text(1), st.as_double(2), st.as_text(3), st.as_text(4)};
    label = k.label();
    if (st.as_int(5) != 0) label += " alignment";  // a variant of the alignment check
  }
  return case_kind_of_job(job.spec).job_label(label, job.spec, job.cells);
}

// What a queue listing shows for the job (study/case_kind.h).
std::string job_name(Store& store, const ClaimedJob& job, const std::string& label) {
  auto st = store.db().prepare("SELECT s.name, COALESCE(j.delta_star, 0) FROM studies s, jobs j WHERE s.id = ? AND j.id = ?");
  st.bind_all(job.study_id, job.job_id);
  if (!st.step()) return label;
  return case_kind_of_job(job.spec).job_name(st.as_text(0), label, st.as_double(1), job.spec);
}

std::vector<long long> studies_of_job(Store& store, long long job_id) {
  std::vector<long long> out;
  auto st = store.db().prepare(
      "SELECT DISTINCT sj.study_id FROM study_jobs sj JOIN studies s ON s.id = sj.study_id "
      "WHERE sj.job_id = ? AND s.status IN ('queued','running')");
  st.bind_all(job_id);
  while (st.step()) out.push_back(st.as_int(0));
  return out;
}

// Counts of the studies this loop works on, from the store (without an ETA).
ProgressCounts store_counts(Store& store, const SchedulerOptions& o) {
  ProgressCounts c;
  c.workers = o.workers;
  for (const auto& s : store.statuses(o.study)) {
    if (!o.study && s.status != "running" && s.status != "queued") continue;
    c.total += s.jobs - s.cancelled;
    c.done += s.done;
    c.failed += s.failed;
    c.running += s.running;
    if (s.mean_wall_s > 0) c.mean_wall_s = s.mean_wall_s;
  }
  return c;
}

double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressTally progress_tally(Store& store, const SchedulerOptions& o) {
  ProgressTally::Sources sources;
  sources.count = [&store, &o] { return store_counts(store, o); };
  // One study: the cost model scaled by measured times (sched/study_eta.h).
  if (o.study)
    sources.eta = [&store, &o]() -> std::optional<double> {
      return study_detail(store, *o.study, o.runs_root, o.workers)["eta"]["seconds"].get<double>();
    };
  sources.now_s = seconds_now;
  return ProgressTally(std::move(sources));
}

// cores(job): the study's rule (study/job_cores.h) capped by the pool's
// cores, or by the threads per job under Slurm; the threads per job when
// the study has no rule.
int cores_of_job(const SchedulerOptions& o, const StudyFacts& facts, const std::array<int, 3>& cells) {
  if (facts.cores.empty()) return o.threads_per_job;
  const int cap = o.cores > 0 ? o.cores : o.threads_per_job;
  const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
  try {
    if (const auto c = job_cores(facts.cores, n, cap)) return *c;
  } catch (const std::exception&) {
  }
  // Validation refuses a rule that is not a number on one of the study's
  // grids; a definition stored before that check falls back, loudly.
  spdlog::warn("cores '{}' is not a finite number at {} cells; the job gets {} thread(s)", facts.cores, n,
               o.threads_per_job);
  return o.threads_per_job;
}

// A job's wall-clock limit: --timeout when given (0 = none), else the
// study's timeout_s, else the default derived from the cost model (an
// external job: from its estimate, `cost`).
double job_timeout_s(const SchedulerOptions& o, const StudyFacts& facts, const ClaimedJob& job,
                     const std::optional<ExternalJobCost>& cost, int cores) {
  if (o.timeout_s >= 0) return o.timeout_s;
  if (facts.timeout_s) return *facts.timeout_s;
  if (cost) return external_job_timeout_s(*cost);
  return default_job_timeout_s(job.cells, cores, apriori_cost_ratio(job.spec, job.cells).ratio);
}

// "0.233 s" below a minute (a small external job's time), else as the plan writes it.
std::string cpu_seconds_text(double s) {
  return std::isfinite(s) && s < 60 ? format_number("%.3g", s) + " s" : human_seconds(s);
}

// "memory unknown (...)": why an external job's memory is not counted.
std::string unknown_memory_note(const ExternalJobCost& c) { return "memory " + c.memory_basis; }

// "estimated memory 200 MiB (basis); CPU 1.2 s (basis)", an unknown one as
// its basis alone ("memory unknown (no cost.mb_per_cell …)"), never "nan MiB".
std::string estimate_sentence(const ExternalJobCost& c) {
  const std::string memory = std::isnan(c.memory_bytes)
                                 ? unknown_memory_note(c)
                                 : "estimated memory " + memory_text(c.memory_bytes) + " (" + c.memory_basis + ")";
  const std::string cpu =
      std::isfinite(c.cpu_s) ? "CPU " + cpu_seconds_text(c.cpu_s) + " (" + c.basis + ")" : "CPU " + c.basis;
  return memory + "; " + cpu;
}

}  // namespace

int recover_stale_jobs(Store& store) {
  std::vector<std::string> orphans;
  {
    auto st = store.db().prepare("SELECT COALESCE(owner,''), COALESCE(external_id,'') FROM jobs WHERE status = 'running'");
    while (st.step())
      if (!owner_alive(st.as_text(0)) && st.as_text(1).rfind("local:", 0) == 0) orphans.push_back(st.as_text(1).substr(6));
  }
  for (const auto& id : orphans)
    if (kill_process_group_if_alive(id)) spdlog::warn("killed an orphaned worker ({})", id);
  const int n = store.requeue_stale([](const std::string& owner) { return owner_alive(owner); });
  if (n > 0) spdlog::warn("requeued {} job(s) left running by a process that is gone", n);
  return n;
}

bool refresh_report(Store& store, long long study_id, const SchedulerOptions& o, ExtrapolationMemo* memo) {
  if (!o.report_dir || o.stop_requested()) return true;  // stopping: the next run writes it
  const auto st = store.statuses(study_id);
  if (st.empty()) return true;
  const auto dir = o.report_dir(st.front().name);
  if (dir.empty()) return true;
  try {
    write_report(store, study_id, dir, o.stop_requested, memo);
    return true;
  } catch (const ReportInterrupted&) {
    spdlog::info("report for study '{}' interrupted by the stop; the next run or `gridfree report` writes it",
                 st.front().name);
    return true;
  } catch (const std::exception& e) {
    spdlog::error("report for study '{}' not written: {}", st.front().name, e.what());
    return false;
  }
}

SchedulerSummary run_scheduler(Store& store, Executor& executor, const SchedulerOptions& o,
                               const std::vector<ClaimedJob>& adopted) {
  SchedulerSummary sum;
  std::map<long long, InFlight> running;
  const BudgetPolicy policy{o.memory_budget_bytes, o.workers, std::max(1, o.workers), o.cores};
  StudyFactsCache facts(store);
  ExternalEstimates estimates(store, facts);
  for (const auto& job : adopted)
    running.emplace(job.job_id, InFlight{job, job_label(store, job), counted_need(estimates.need(job), policy),
                                         cores_of_job(o, facts.of(job.study_id), job.cells)});
  const NeedOf need = [&estimates](long long study_id, long long job_id, const std::array<int, 3>& cells) {
    return estimates.need(study_id, job_id, cells);
  };
  const CoresOf cores = [&o, &facts](long long study_id, const std::array<int, 3>& cells) {
    return cores_of_job(o, facts.of(study_id), cells);
  };
  HeadReservation reservation;
  ProgressTally tally = progress_tally(store, o);
  // A poll's queue changes in one commit, not one each: a poll moves up to
  // max_queued tasks (BENCHMARKS.md "Prepared statements kept").
  auto record_updates = [&] {
    const std::vector<JobUpdate> updates = executor.take_updates();
    if (updates.empty()) return;
    Transaction tx(store.db());
    for (const auto& u : updates) store.set_queue_state(u.job_id, u.external_id, u.state, u.reason);
    tx.commit();
  };

  // Reports of studies whose series finished, paced (sched/report_pacer.h):
  // all pending ones, or only those whose pause is over.
  ReportPacer pacer;
  std::map<long long, ExtrapolationMemo> memos;  // per study, between its report writes
  auto write_reports = [&](bool all_pending) {
    for (long long id : pacer.pending(all_pending ? std::nullopt : std::optional<double>(seconds_now()))) {
      const double started = seconds_now();
      if (!refresh_report(store, id, o, &memos[id])) ++sum.reports_failed;
      else sum.reports_current = true;
      pacer.written(id, started, seconds_now());
    }
  };
  // Studies whose jobs were all done already (reused) finish right away.
  auto sweep = [&](const std::vector<long long>& studies) {
    for (long long id : studies) {
      const int n = finish_ready_series(store, id);
      sum.series_finished += n;
      if (n > 0) pacer.series_finished(id);
    }
    write_reports(false);
  };
  // After a job's final result: only the series of that job can have become
  // ready (sched/series_finish.h).
  auto sweep_job = [&](long long job_id) {
    for (long long id : o.study ? std::vector<long long>{*o.study} : studies_of_job(store, job_id)) {
      const int n = finish_series_of_job(store, id, job_id, facts.of(id).adaptive);
      sum.series_finished += n;
      if (n > 0) pacer.series_finished(id);
    }
    write_reports(false);
  };
  sweep(o.study ? std::vector<long long>{*o.study} : store.active_studies());

  for (;;) {
    if (o.stop_requested()) break;
    // 1. start while there is capacity
    while (static_cast<int>(running.size()) < o.workers && !o.stop_requested()) {
      auto job = claim_within_budget(store, o.study, o.owner, budget_use(running), policy, reservation, need, cores);
      if (!job) break;
      const std::optional<ExternalJobCost> cost = estimates.of(*job);
      InFlight f{*job, job_label(store, *job),
                 counted_need(cost ? cost->memory_bytes : job_memory_estimate_bytes(job->cells), policy),
                 cores_of_job(o, facts.of(job->study_id), job->cells)};
      if (!facts.of(job->study_id).cores.empty())
        spdlog::info("{}: {} core(s) (cores = {}, at most {})", f.label, f.cores, facts.of(job->study_id).cores,
                     o.cores > 0 ? o.cores : o.threads_per_job);
      if (o.memory_budget_bytes > 0 && cost && std::isnan(cost->memory_bytes))
        spdlog::info("{}: {}: it runs alone within the memory budget", f.label, unknown_memory_note(*cost));
      else if (o.memory_budget_bytes > 0 && f.memory_bytes > o.memory_budget_bytes)
        spdlog::warn("{}: its estimated memory {} exceeds the memory budget {}; it runs alone", f.label,
                     memory_text(f.memory_bytes), memory_text(o.memory_budget_bytes));
      else if (cost)  // where an external job's estimates come from (study/external_cost.h)
        spdlog::info("{}: {}", f.label, estimate_sentence(*cost));
      JobLaunch launch;
      launch.job_id = job->job_id;
      launch.job_hash = job->job_hash;
      launch.threads = f.cores;
      if (!facts.of(job->study_id).cores.empty()) launch.cores = f.cores;
      launch.timeout_s = job_timeout_s(o, facts.of(job->study_id), *job, cost, f.cores);
      launch.cells = job->cells;
      launch.cores_are_tasks = case_kind_of_job(job->spec).cores_are_tasks();
      if (cost) {  // an external code: gridfree's model does not describe it (exec/executor.h)
        launch.own_estimate = true;
        launch.memory_bytes = cost->memory_bytes;
        launch.memory_basis = cost->memory_basis;
      } else {
        launch.bed_cache = bed_cache_dir(o.runs_root);
      }
      launch.name = job_name(store, *job, f.label);
      try {
        launch.run_dir = prepare_run_dir(o.runs_root, job->job_hash, job->spec.dump(2));
      } catch (const std::exception& e) {
        store.release(job->job_id, o.owner, std::string("run directory: ") + e.what());
        throw;
      }
      store.set_job_paths(job->job_id, (launch.run_dir / "result.json").string());
      launch.hold = true;  // recorded before it runs: a restart can always find it
      executor.start(launch);
      if (auto ext = executor.external_id(job->job_id); !ext.empty())
        store.set_job_external_id(job->job_id, ext);
      executor.release(job->job_id);
      running.emplace(job->job_id, std::move(f));
      tally.job_started();
      if (o.progress) o.progress->update(tally.current());
    }
    executor.flush();
    record_updates();
    // Nothing running and nothing to claim: done (run) or idle (daemon).
    if (running.empty()) {
      if (o.study) sweep({*o.study});
      else sweep(store.active_studies());
      bool others_working = false;
      if (o.study) {
        const auto st = store.statuses(o.study);
        others_working = !st.empty() && (st.front().running > 0 || st.front().queued > 0);
      }
      if (o.stop_when_idle && !others_working) break;
      write_reports(true);
      const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.idle_poll_s);
      while (std::chrono::steady_clock::now() < until && !o.stop_requested())
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      continue;
    }
    // 2. wait for one to finish
    auto exit = executor.wait_any(0.25);
    record_updates();
    if (!exit) continue;
    auto it = running.find(exit->job_id);
    if (it == running.end()) continue;
    const InFlight f = it->second;
    running.erase(it);
    // 3. record it
    sum.reports_current = false;
    JobOutcome out = classify_exit(*exit);
    std::string what = f.label + ": ";
    bool failed = true;  // logged at warn unless converged or released
    if (out.kind == OutcomeKind::kFinal) {
      case_kind_of_job(f.job.spec).take_result(f.job.spec, f.job.cells, out.row.result_json, out.row.cells);
      estimates.finished(f.job, out.row);
      if (store.record_result(f.job.job_id, o.owner, out.row)) remove_checkpoint(exit->run_dir);
      ++sum.finished;
      tally.job_finished(out.row.status == "converged", out.row.wall_s);
      if (out.row.status == "converged") {
        ++sum.converged;
        failed = false;
        what += converged_message(out.row);
      } else {
        ++sum.failed;
        what += out.row.status + ": " + out.row.reason;
      }
    } else if (out.kind == OutcomeKind::kRetryable) {
      const bool requeued = store.record_retryable_failure(f.job.job_id, o.owner, out.row, o.max_attempts);
      if (requeued) {
        tally.job_requeued();
        ++sum.retried;
        what += "will retry: " + out.row.reason;
      } else {
        remove_checkpoint(exit->run_dir);
        tally.job_finished(false, out.row.wall_s);
        ++sum.finished;
        ++sum.failed;
        what += "failed: " + out.row.reason;
      }
    } else {
      store.release(f.job.job_id, o.owner, out.row.reason);
      tally.job_requeued();
      failed = false;
      what += "released: " + out.row.reason;
    }
    if (o.progress) o.progress->job_finished(what, tally.current(), failed);
    sweep_job(f.job.job_id);
  }

  if (o.stop_requested()) {
    sum.interrupted = true;
    // The jobs' error says why: sbatch's refusal when that stopped the run.
    const auto fatal = executor.fatal_error();
    const std::string reason = fatal ? "not started: " + *fatal + "; requeued for the next run"
                                     : "interrupted: requeued for the next run";
    for (long long id : executor.kill_all()) {
      store.release(id, o.owner, reason);
      ++sum.requeued;
      sum.reports_current = false;
    }
    running.clear();
  }
  if (!(o.study && o.stop_when_idle)) write_reports(true);  // `run` writes its final report itself
  if (o.progress) o.progress->finish();
  return sum;
}

}  // namespace gridfree
