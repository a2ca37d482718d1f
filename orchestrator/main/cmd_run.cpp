// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree run | submit | daemon: put a study in the database and work the queue.
//   --replace (run, submit): a changed study under a stored name replaces it
//   run     = validate + submit + schedule that study until done + report
//   submit  = validate + submit (a daemon or a later run does the work)
//   daemon  = schedule every queued study until SIGINT/SIGTERM (an existing
//             database only; log lines carry their time)
// Validation comes first: an invalid study never opens (or creates) the database.
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include <spdlog/spdlog.h>

#include "cmd_study.h"
#include "executor_flags.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "job/memory_estimate.h"
#include "sched/adopt.h"
#include "exec/worker_path.h"
#include "sched/memory_budget.h"
#include "sched/recollect.h"
#include "sched/series_finish.h"
#include "sched/stop_signal.h"
#include "study/case_kind.h"

namespace gridfree::cli {
namespace {

struct RunOptions {
  std::string study_file;
  std::string db = kDefaultDb;
  int jobs = default_jobs();
  ExecutorFlags executor;
  double timeout_s = kDerivedTimeout;
  std::string out;
  bool replace = false;
  std::string memory_budget;  // "" = MemAvailable
};

// The local executor's memory budget (sched/memory_budget.h), logged with
// its source; none under Slurm (the cluster places the jobs).
void apply_memory_budget(SchedulerOptions& options, const ExecutorFlags& executor, const std::string& flag) {
  if (executor.kind == "slurm") {
    if (!flag.empty()) throw InputError("--memory-budget", "applies to the local executor only (Slurm gets --mem)");
    return;
  }
  const MemoryBudget budget = resolve_memory_budget(flag);
  options.memory_budget_bytes = budget.bytes;
  spdlog::info("memory budget {} ({}): a job starts when the estimates of the running jobs and its own fit",
               memory_text(budget.bytes), budget.source);
}

constexpr const char* kTimeoutHelp =
    "per-job timeout: seconds > 0, or 'none' (default: the study's timeout_s, else 20 x the plan's estimate, at "
    "least 1 h)";

constexpr const char* kMemoryBudgetHelp =
    "memory the running jobs' estimates may add up to, e.g. 12G (default: MemAvailable at start; local executor)";

SubmitResult submit_study(Store& store, const Study& study, const ExpandedStudy& ex, bool replace) {
  const SubmitResult r = store.submit(study, ex, replace);
  // Jobs no study needs any more are kept, reusable (store/unneeded_jobs.h).
  const std::string kept = std::to_string(r.jobs_unneeded.size()) +
                           " job(s) no study needs any more kept (reused if asked for again; `gridfree gc` removes them)";
  if (r.replaced && r.jobs_changed)
    spdlog::info("'{}': its template or code version changed since it was stored: its jobs were replaced; {}",
                 study.name, kept);
  else if (r.replaced)
    spdlog::info("'{}': the stored definition was replaced; {}", study.name, kept);
  if (r.created)
    spdlog::info("submitted '{}': {} series, {} jobs ({} new, {} already done)", study.name, ex.series.size(),
                 r.jobs_total, r.jobs_new, r.jobs_reused);
  else if (r.uncancelled)
    spdlog::info("'{}' was cancelled: {} cancelled job(s) queued again, resuming", study.name, r.jobs_requeued);
  else
    spdlog::info("'{}' is already in the database: resuming", study.name);
  return r;
}

// Finished external jobs whose collect section changed: read again from
// their run folders, not rerun (sched/recollect.h).
void recollect_finished_jobs(Store& store, long long study_id, const std::filesystem::path& runs_root) {
  const RecollectSummary rc = recollect_study(store, study_id, default_worker_path(), runs_root);
  if (rc.recollected > 0) spdlog::info("re-collected {} finished job(s) with the study's collect section", rc.recollected);
  if (rc.failed > 0)
    spdlog::warn("{} job(s) could not be re-collected (their previous values stay; `gridfree run` or a starting "
                 "`gridfree daemon` tries again): {}",
                 rc.failed, rc.first_error);
}

int run_study(const RunOptions& ro) {
  // 1. Validate before touching the database.
  const Study study = parse_study(ro.study_file);
  const ExpandedStudy ex = expand(study);
  auto options = scheduler_options(ro.db, ro.jobs, ro.timeout_s, ro.out);
  apply_memory_budget(options, ro.executor, ro.memory_budget);
  // A study's slurm block (checked by parse_study) applies to --executor
  // slurm; a local run ignores it, so one file serves both.
  const bool has_slurm = study.definition.is_object() && study.definition.contains("slurm");
  if (has_slurm && ro.executor.kind != "slurm")
    spdlog::info("the study's \"slurm\" settings apply to --executor slurm only; this local run ignores them");
  auto executor = make_executor(ro.executor, ro.db, ro.jobs, options,
                                has_slurm && ro.executor.kind == "slurm" ? &study.definition["slurm"] : nullptr);
  // 2. Submit (or resume).
  Store store(ro.db, true);
  const SubmitResult sub = submit_study(store, study, ex, ro.replace);
  if (case_kind(study).results_recollectable()) recollect_finished_jobs(store, sub.study_id, options.runs_root);
  const auto adopted = adopt_stale_jobs(store, *executor, options.owner, options.timeout_s);
  recover_stale_jobs(store);
  // 3. Work the study until it is done.
  StopSignals signals;
  Progress progress(isatty(STDERR_FILENO) != 0);
  options.study = sub.study_id;
  // A fatal executor error (sbatch refused a submission for good) stops the
  // loop like a signal: the jobs in flight are requeued, no attempt spent.
  options.stop_requested = [&signals, &executor] { return signals.requested() || executor->fatal_error(); };
  options.progress = &progress;
  const SchedulerSummary sum = run_scheduler(store, *executor, options, adopted);
  progress.finish();
  if (const auto fatal = executor->fatal_error())
    throw InputError("--executor", *fatal + "; nothing more was submitted, the study's jobs are queued again: fix "
                                            "the cause and run again");
  // 4. Report and exit code.
  // Written once: the scheduler's write after the last job stands unless
  // something changed since (sched/scheduler.h, reports_current). After a
  // stop the report is left for the next run (a large study's report takes
  // minutes; the stop must not wait for it).
  const bool changed = finish_ready_series(store, sub.study_id) > 0 || !sum.reports_current;
  const bool report_ok =
      sum.interrupted || ((!changed || refresh_report(store, sub.study_id, options)) && sum.reports_failed == 0);
  const auto st = store.statuses(sub.study_id).front();
  std::cerr << "study " << st.name << ": " << st.status << " — " << st.converged << "/" << st.jobs
            << " jobs converged, " << st.failed << " failed";
  if (sum.interrupted) std::cerr << " (interrupted; run again to resume)";
  const bool cancelled = !sum.interrupted && st.status == "cancelled";
  if (cancelled) std::cerr << " (cancelled; run again to resume)";
  // Only a report that exists is named; a failed write is an error (exit 1).
  const auto html = options.report_dir(st.name) / "report.html";
  std::error_code ec;
  if (sum.interrupted)
    std::cerr << "\nreport: not rewritten (interrupted; the next run or `gridfree report` writes it)\n";
  else if (report_ok && std::filesystem::is_regular_file(html, ec)) std::cerr << "\nreport: " << html.string() << '\n';
  else std::cerr << "\nreport: not written (see the error above); the results are in the database\n";
  if (sum.interrupted || cancelled) return to_int(ExitCode::kInterrupted);  // a cancel is an interruption
  if (!report_ok) return to_int(ExitCode::kInternalError);
  if (st.status == "done") return to_int(ExitCode::kOk);
  return to_int(ExitCode::kNotConverged);
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("run", "submit a study and work it until done, then write its report");
  auto ro = std::make_shared<RunOptions>();
  sub->add_option("STUDY", ro->study_file, "study JSON file")->required();
  sub->add_option("--db", ro->db, "SQLite database")->capture_default_str();
  sub->add_option("-j,--jobs", ro->jobs, "jobs at a time (default: cores)");
  add_executor_flags(sub, ro->executor);
  auto timeout_text = std::make_shared<std::string>();
  auto* timeout = sub->add_option("--timeout", *timeout_text, kTimeoutHelp);
  sub->add_option("--out", ro->out, "report folder (default reports/<study>)");
  sub->add_option("--memory-budget", ro->memory_budget, kMemoryBudgetHelp);
  sub->add_flag("--replace", ro->replace,
                "replace a stored study of the same name whose definition differs (finished jobs are reused)");
  sub->callback([ro, timeout, timeout_text, &exit_code] {
    ro->timeout_s = timeout_flag(timeout, *timeout_text);
    exit_code = run_study(*ro);
  });
}

void add_submit_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("submit", "validate a study and queue its jobs");
  auto file = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  auto replace = std::make_shared<bool>(false);
  sub->add_option("STUDY", *file, "study JSON file")->required();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->add_flag("--replace", *replace,
                "replace a stored study of the same name whose definition differs (finished jobs are reused)");
  sub->callback([file, db, replace, &exit_code] {
    const Study study = parse_study(*file);
    const ExpandedStudy ex = expand(study);
    Store store(*db, true);
    const SubmitResult r = submit_study(store, study, ex, *replace);
    if (case_kind(study).results_recollectable()) recollect_finished_jobs(store, r.study_id, runs_root_for(*db));
    if (r.uncancelled)
      std::cout << "requeued cancelled study " << study.name << ": " << r.jobs_requeued
                << " cancelled job(s) queued again (" << r.jobs_total << " jobs in all)\n";
    else
      std::cout << (r.created ? "submitted " : "already submitted (nothing changed) ") << study.name << ": "
                << ex.series.size() << " series, " << r.jobs_total << " jobs\n";
    exit_code = to_int(ExitCode::kOk);
  });
}

void add_daemon_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("daemon", "work every submitted study until SIGINT/SIGTERM");
  auto db = std::make_shared<std::string>(kDefaultDb);
  auto jobs = std::make_shared<int>(default_jobs());
  auto executor_flags = std::make_shared<ExecutorFlags>();
  auto timeout = std::make_shared<double>(kDerivedTimeout);
  auto timeout_text = std::make_shared<std::string>();
  auto memory_budget = std::make_shared<std::string>();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->add_option("--memory-budget", *memory_budget, kMemoryBudgetHelp);
  sub->add_option("-j,--jobs", *jobs, "jobs at a time (default: cores)");
  add_executor_flags(sub, *executor_flags);
  auto* timeout_option = sub->add_option("--timeout", *timeout_text, kTimeoutHelp);
  sub->callback([=, &exit_code] {
    *timeout = timeout_flag(timeout_option, *timeout_text);
    // A daemon runs for days: every log line carries its time.
    spdlog::set_pattern("[%Y-%m-%d %H:%M:%S] %^[%l]%$ %v");
    // The executor first: a missing Slurm command is refused before the
    // database is opened. A mistyped --db would wait forever on an empty
    // new database.
    auto options = scheduler_options(*db, *jobs, *timeout, {});
    apply_memory_budget(options, *executor_flags, *memory_budget);
    auto executor = make_executor(*executor_flags, *db, *jobs, options);
    const auto store_ptr = open_existing_store(*db);
    Store& store = *store_ptr;
    // External studies whose collect section changed after their jobs
    // finished (a submit that could not re-collect): read again now.
    for (long long id : store.active_studies())
      if (case_kind_of_definition(store.study_definition(id)).results_recollectable())
        recollect_finished_jobs(store, id, options.runs_root);
    const auto adopted = adopt_stale_jobs(store, *executor, options.owner, options.timeout_s);
    recover_stale_jobs(store);
    StopSignals signals;
    Progress progress(false);
    options.stop_when_idle = false;
    options.stop_requested = [&signals, &executor] { return signals.requested() || executor->fatal_error(); };
    options.progress = &progress;
    spdlog::info("daemon: working {} with {} job(s) at a time (SIGINT/SIGTERM stops)", *db, *jobs);
    const SchedulerSummary sum = run_scheduler(store, *executor, options, adopted);
    if (sum.requeued > 0)
      spdlog::info("daemon: stopped; {} job(s) finished this session, {} in-flight job(s) requeued", sum.finished,
                   sum.requeued);
    else
      spdlog::info("daemon: stopped; {} job(s) finished this session", sum.finished);
    if (sum.reports_failed > 0) spdlog::error("daemon: {} report(s) could not be written", sum.reports_failed);
    if (const auto fatal = executor->fatal_error())
      throw InputError("--executor", *fatal + "; the jobs in flight are queued again");
    exit_code = to_int(sum.reports_failed > 0 ? ExitCode::kInternalError : ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
