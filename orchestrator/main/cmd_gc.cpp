// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree gc [--dry-run] [--db F]: removes the jobs no study needs any more
// (store/unneeded_jobs.h: left by a replaced study or a changed template),
// with their results, events and run folders; an emptied shard folder of
// the run folders goes too. --dry-run lists them with their size on disk
// and removes nothing. Nothing else removes them but `gridfree delete`.
#include <cstdio>
#include <iostream>

#include "cmd_study.h"
#include "core/exit_codes.h"
#include "exec/executor.h"
#include "exec/run_folders.h"
#include "store/unneeded_jobs.h"
#include "study/study_plan.h"

namespace gridfree::cli {
namespace {

// "  3fa2c1d9e8b0  done       cavity  400 cells  1.2 MiB"
std::string gc_line(const UnneededJob& j, std::uintmax_t bytes) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-12.12s  %-9s  %-16s %10lld cells  %s", j.hash.c_str(), j.status.c_str(),
                j.case_name.c_str(), j.cells, human_bytes(static_cast<double>(bytes)).c_str());
  return line;
}

}  // namespace

void add_gc_command(CLI::App& app, int& exit_code) {
  auto* sub = app.add_subcommand("gc", "remove the jobs no study needs any more (with their results and run folders)");
  auto db = std::make_shared<std::string>(kDefaultDb);
  auto dry_run = std::make_shared<bool>(false);
  sub->add_flag("--dry-run", *dry_run, "list what would be removed, with sizes on disk; remove nothing");
  sub->add_option("--db", *db, "SQLite database")->capture_default_str();
  sub->callback([=, &exit_code] {
    auto store = open_existing_store(*db);
    const auto root = runs_root_for(*db);
    const std::vector<UnneededJob> jobs = *dry_run ? unneeded_jobs(store->db()) : remove_unneeded_jobs(*store);
    std::uintmax_t total = 0;
    std::vector<std::string> lines;
    for (const auto& j : jobs) {
      const std::uintmax_t bytes = run_folder_bytes(root, j.hash);
      total += bytes;
      lines.push_back(gc_line(j, bytes));
      // A job a submit made again since (the same hash) keeps its folder.
      if (!*dry_run && !job_hash_stored(store->db(), j.hash)) remove_run_folder(root, j.hash);
    }
    std::cout << (*dry_run ? "would remove " : "removed ") << jobs.size() << " job(s) no study needs any more ("
              << human_bytes(static_cast<double>(total)) << " on disk)" << (jobs.empty() ? "" : ":") << '\n';
    for (const auto& l : lines) std::cout << l << '\n';
    exit_code = to_int(ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
