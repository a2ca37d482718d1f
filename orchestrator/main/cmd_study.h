// SPDX-License-Identifier: GPL-3.0-or-later
// Helpers shared by the study subcommands (validate, plan, run, submit,
// daemon, status, report, cancel) and their registration functions.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "exec/executor.h"
#include "sched/scheduler.h"
#include "store/store.h"
#include "study/study.h"

namespace gridfree::cli {

void add_validate_command(CLI::App& app, int& exit_code);
void add_plan_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
void add_submit_command(CLI::App& app, int& exit_code);
void add_daemon_command(CLI::App& app, int& exit_code);
void add_status_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
void add_cancel_command(CLI::App& app, int& exit_code);
void add_delete_command(CLI::App& app, int& exit_code);
void add_retry_command(CLI::App& app, int& exit_code);
void add_gc_command(CLI::App& app, int& exit_code);

inline constexpr const char* kDefaultDb = "gridfree.sqlite";

int default_jobs();  // number of cores

// Opens an existing database (throws InputError naming --db if missing).
std::unique_ptr<Store> open_existing_store(const std::filesystem::path& db);

// The id of the stored study `name` (throws InputError naming STUDY if there is none).
long long require_study(Store& store, const std::string& name);

// --timeout value meaning "derived from the cost model" (sched/job_timeout.h).
inline constexpr double kDerivedTimeout = -1;

// The --timeout of run/daemon: kDerivedTimeout when the flag was not given,
// else its text: a positive number of seconds, or "none" (returned as 0,
// no timeout); anything else is refused naming the flag.
double timeout_flag(const CLI::Option* option, const std::string& text);

// Scheduler options common to run and daemon.
SchedulerOptions scheduler_options(const std::filesystem::path& db, int jobs, double timeout_s,
                                   const std::filesystem::path& out_override);

}  // namespace gridfree::cli
