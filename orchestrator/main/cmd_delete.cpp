// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree delete STUDY [--db F]: removes a study, its series, their
// extrapolations and uncertainties, its job links and events, then those of
// its jobs (and results, and run folders) that no other study uses. Jobs
// shared with other studies stay, and so do jobs other studies left
// unneeded (`gridfree gc`). The report folder is left alone. Refused while
// one of the study's jobs is running.
#include <iostream>

#include "cmd_study.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "exec/executor.h"
#include "exec/run_folders.h"

namespace gridfree::cli {

void add_delete_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("delete", "remove a study and the jobs no other study uses");
  auto name = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  sub->add_option("STUDY", *name, "study name")->required();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    const auto removed = store->delete_study(*name);
    if (!removed) throw InputError("STUDY", "no study named '" + *name + "' in " + *db);
    remove_run_folders(runs_root_for(*db), *removed);
    std::cout << "deleted " << *name << "; " << removed->size() << " job(s) no other study uses removed\n";
    exit_code = to_int(ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
