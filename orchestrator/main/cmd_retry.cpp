// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree retry STUDY: puts a study's failed jobs back in the queue (attempts
// reset, their series and the study open again); `run` or a daemon then
// works them. Results of converged jobs are kept.
#include <iostream>

#include "cmd_study.h"
#include "core/exit_codes.h"

namespace gridfree::cli {

void add_retry_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("retry", "queue a study's failed jobs again");
  auto name = std::make_shared<std::string>();
  auto db = std::make_shared<std::string>(kDefaultDb);
  sub->add_option("STUDY", *name, "study name")->required();
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    const int n = store->retry_failed(require_study(*store, *name));
    std::cout << "requeued " << n << " failed job(s) of " << *name
              << (n > 0 ? " (gridfree run or a daemon works them)" : "") << '\n';
    exit_code = to_int(ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
