// SPDX-License-Identifier: GPL-3.0-or-later
// Online backup and VACUUM of a database (store/db_backup.h).
#include "store/db_backup.h"

#include <string>

#include "core/input_error.h"
#include "store/database_file.h"
#include "store/sqlite.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

std::uintmax_t file_size_or_zero(const fs::path& f) {
  std::error_code ec;
  const auto n = fs::file_size(f, ec);
  return ec ? 0 : n;
}

std::uintmax_t size_with_wal(const fs::path& db) { return file_size_or_zero(db) + file_size_or_zero(db.string() + "-wal"); }

void check_copy_path(const fs::path& db, const fs::path& copy) {
  std::error_code ec;
  if (fs::exists(copy, ec))
    throw InputError("FILE", "'" + copy.string() + "' exists: a backup is written to a new file only (give "
                                                    "another name, or remove it first)");
  const auto folder = fs::absolute(copy, ec).parent_path();
  if (!fs::is_directory(folder, ec))
    throw InputError("FILE", "'" + copy.string() + "' is in a folder that does not exist (" + folder.string() + ")");
  if (fs::absolute(copy, ec) == fs::absolute(db, ec)) throw InputError("FILE", "is the database itself");
}

// The destination connection, closed (and its partial file removed) on a throw.
struct BackupDestination {
  sqlite3* db = nullptr;
  fs::path file;
  bool keep = false;
  ~BackupDestination() {
    sqlite3_close(db);
    if (!keep) {
      std::error_code ec;
      fs::remove(file, ec);
      fs::remove(file.string() + "-journal", ec);
    }
  }
};

}  // namespace

BackupSummary backup_database(const fs::path& db_file, const fs::path& copy) {
  check_database_file(db_file, false);
  check_copy_path(db_file, copy);
  Database source(db_file, false);
  BackupDestination dest;
  dest.file = copy.string() + ".part";
  std::error_code ec;
  fs::remove(dest.file, ec);  // left by a backup killed earlier
  if (const int rc = sqlite3_open_v2(dest.file.c_str(), &dest.db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
      rc != SQLITE_OK)
    throw InputError("FILE", "cannot create '" + dest.file.string() + "': " + sqlite3_errstr(rc));
  sqlite3_backup* b = sqlite3_backup_init(dest.db, "main", source.handle(), "main");
  if (b == nullptr) throw SqliteError(std::string("backup: ") + sqlite3_errmsg(dest.db), sqlite3_errcode(dest.db));
  // -1: every page in one step, one read transaction of the source: one
  // committed state. BUSY (the source's busy handler gave up) is retried
  // by the same wait.
  int rc = SQLITE_OK;
  for (int attempt = 0;; ++attempt) {
    rc = sqlite3_backup_step(b, -1);
    if (!busy_code(rc) || !source.wait_busy(attempt)) break;
  }
  BackupSummary out;
  out.pages = sqlite3_backup_pagecount(b);
  sqlite3_backup_finish(b);
  if (rc != SQLITE_DONE) {
    const std::string words = sqlite3_errstr(rc);
    if (damaged_code(rc)) throw SqliteError("the database " + db_file.string() + " is damaged (SQLite: " + words +
                                                "): it cannot be backed up page by page; docs/DATABASE.md "
                                                "\"Recovery\" says how to save what it holds",
                                            rc);
    throw SqliteError("backup of " + db_file.string() + ": " + words, rc);
  }
  sqlite3_close(dest.db);
  dest.db = nullptr;
  fs::rename(dest.file, copy);
  dest.keep = true;
  out.bytes = file_size_or_zero(copy);
  return out;
}

VacuumSummary vacuum_database(const fs::path& db_file) {
  check_database_file(db_file, false);
  VacuumSummary out;
  out.bytes_before = size_with_wal(db_file);
  {
    Database db(db_file, false);
    db.exec("VACUUM");
    auto st = db.prepare("PRAGMA wal_checkpoint(TRUNCATE)");
    st.step();
  }
  out.bytes_after = size_with_wal(db_file);
  return out;
}

}  // namespace gridfree
