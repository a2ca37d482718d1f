// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree validate|plan|run|submit|daemon|status|report|cancel: registration
// and the helpers they share (database, executor, scheduler options).
#include "cmd_study.h"

#include <charconv>
#include <limits>
#include <cmath>
#include <thread>

#include <spdlog/spdlog.h>

#include "core/input_error.h"
#include "exec/executor.h"
#include "commands.h"
#include "store/owner.h"

namespace gridfree::cli {

void add_study_commands(CLI::App& app, int& exit_code) {
  add_validate_command(app, exit_code);
  add_plan_command(app, exit_code);
  add_run_command(app, exit_code);
  add_submit_command(app, exit_code);
  add_daemon_command(app, exit_code);
  add_status_command(app, exit_code);
  add_report_command(app, exit_code);
  add_cancel_command(app, exit_code);
  add_delete_command(app, exit_code);
  add_retry_command(app, exit_code);
  add_gc_command(app, exit_code);
}

int default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

std::unique_ptr<Store> open_existing_store(const std::filesystem::path& db) {
  return std::make_unique<Store>(db, false);  // a missing file is refused (store/database_file.h)
}

long long require_study(Store& store, const std::string& name) {
  const auto id = store.study_id(name);
  if (!id) throw InputError("STUDY", "no study named '" + name + "' in " + store.file().string());
  return *id;
}

double timeout_flag(const CLI::Option* option, const std::string& text) {
  if (option->count() == 0) return kDerivedTimeout;
  if (text == "none") return 0;  // SchedulerOptions::timeout_s: 0 = none
  double value = std::numeric_limits<double>::quiet_NaN();
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || value <= 0)
    throw InputError("--timeout", "must be a positive number of seconds, or 'none' for no timeout (leave it out for "
                                  "the default derived from the cost model), not '" + text + "'");
  return value;
}

SchedulerOptions scheduler_options(const std::filesystem::path& db, int jobs, double timeout_s,
                                   const std::filesystem::path& out_override) {
  if (jobs < 1) throw InputError("-j", "needs at least 1 job at a time");
  SchedulerOptions o;
  o.workers = jobs;
  o.threads_per_job = std::max(1, default_jobs() / jobs);
  o.cores = std::max(default_jobs(), jobs);  // -j jobs of threads_per_job cores always fit (sched/budget.h)
  spdlog::info("{} job(s) at a time, {} thread(s) each ({} cores)", jobs, o.threads_per_job, default_jobs());
  o.timeout_s = timeout_s;
  o.runs_root = runs_root_for(db);
  o.owner = this_process_owner();
  o.report_dir = [out_override](const std::string& name) {
    return out_override.empty() ? std::filesystem::path("reports") / name : out_override;
  };
  return o;
}

}  // namespace gridfree::cli
