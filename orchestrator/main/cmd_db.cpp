// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree db check|backup|vacuum [--db F]: the database file itself
// (docs/DATABASE.md "Checking, backing up, compacting").
//   check        SQLite's integrity check and gridfree's invariants
//                (store/db_check.h); exit 0 sound, 1 problems found (listed)
//   backup FILE  a consistent copy while run/daemon write (store/db_backup.h)
//   vacuum       rewrites the file without its free pages
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cmd_study.h"
#include "commands.h"
#include "core/exit_codes.h"
#include "store/db_backup.h"
#include "store/db_check.h"

namespace gridfree::cli {
namespace {

std::string mib_text(std::uintmax_t bytes) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

int run_db_check(const std::string& db) {
  const DbCheckReport r = check_database(db);
  if (r.clean()) {
    std::cout << db << ": sound (schema version " << r.schema_version << "; " << r.studies << " studies, " << r.jobs
              << " jobs, " << r.results << " results)\n";
    return to_int(ExitCode::kOk);
  }
  std::cout << db << ": " << r.problems.size() << " problem(s) found:\n";
  for (const auto& p : r.problems) std::cout << "  - " << p << '\n';
  std::cout << "docs/DATABASE.md \"Recovery\" says what to do.\n";
  return 1;  // as fsck: problems found (docs/INTERFACE.md)
}

}  // namespace

void add_db_command(CLI::App& app, int& exit_code) {
  auto* db_cmd = app.add_subcommand("db", "check, back up or compact the database file");
  db_cmd->require_subcommand(1);
  auto db = std::make_shared<std::string>(kDefaultDb);

  auto* check = db_cmd->add_subcommand(
      "check", "SQLite's integrity check and gridfree's invariants; exit 0 sound, 1 problems found (listed)");
  check->add_option("--db", *db, "SQLite database")->capture_default_str();
  check->callback([db, &exit_code] { exit_code = run_db_check(*db); });

  auto copy = std::make_shared<std::string>();
  auto* backup = db_cmd->add_subcommand(
      "backup", "copy the database to FILE, consistent while run/daemon write (SQLite's online backup)");
  backup->add_option("FILE", *copy, "the copy (a new file)")->required();
  backup->add_option("--db", *db, "SQLite database")->capture_default_str();
  backup->callback([db, copy, &exit_code] {
    const BackupSummary s = backup_database(*db, *copy);
    std::cout << "backed up " << *db << " to " << *copy << ": " << s.pages << " pages, " << mib_text(s.bytes)
              << " (restore: stop gridfree on " << *db << ", remove " << *db << "-wal and -shm, copy " << *copy
              << " over it)\n";
    exit_code = to_int(ExitCode::kOk);
  });

  auto* vacuum = db_cmd->add_subcommand("vacuum", "rewrite the database without its free pages");
  vacuum->add_option("--db", *db, "SQLite database")->capture_default_str();
  vacuum->callback([db, &exit_code] {
    const VacuumSummary s = vacuum_database(*db);
    std::cout << "vacuumed " << *db << ": " << mib_text(s.bytes_before) << " -> " << mib_text(s.bytes_after)
              << " (with its -wal)\n";
    exit_code = to_int(ExitCode::kOk);
  });
}

}  // namespace gridfree::cli
