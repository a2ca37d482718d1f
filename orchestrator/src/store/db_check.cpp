// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree db check` (store/db_check.h).
#include "store/db_check.h"

#include <functional>

#include "core/input_error.h"
#include "store/database_file.h"
#include "store/schema.h"
#include "store/sqlite.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// Runs `sql`; each row becomes a problem by `describe`, at most
// kDbCheckMaxListed of them listed.
void collect_problems(Database& db, const std::string& sql, const std::function<std::string(const Statement&)>& describe,
             std::vector<std::string>& problems) {
  auto st = db.prepare(sql);
  long long n = 0;
  while (st.step()) {
    if (++n <= kDbCheckMaxListed) problems.push_back(describe(st));
  }
  if (n > kDbCheckMaxListed)
    problems.push_back("... and " + std::to_string(n - kDbCheckMaxListed) + " more like the one above");
}

long long count_rows(Database& db, const std::string& sql) {
  auto st = db.prepare(sql);
  return st.step() ? st.as_int(0) : 0;
}

std::string job_label(const Statement& st) {  // columns 0, 1: id, hash
  return "job " + std::to_string(st.as_int(0)) + " (" + st.as_text(1).substr(0, 12) + ")";
}

void check_sqlite_integrity(Database& db, std::vector<std::string>& problems) {
  collect_problems(db, "PRAGMA integrity_check(" + std::to_string(kDbCheckMaxListed) + ")",
          [](const Statement& st) {
            std::string text = st.as_text(0);  // one row may hold several lines
            for (auto at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 1))
              text.insert(at + 1, "    ");
            return "SQLite integrity_check: " + text;
          },
          problems);
  if (!problems.empty() && problems.back() == "SQLite integrity_check: ok") problems.pop_back();
  collect_problems(db, "PRAGMA foreign_key_check",
          [](const Statement& st) {
            return "table " + st.as_text(0) + " row " + std::to_string(st.as_int(1)) + " refers to a missing row of " +
                   st.as_text(2);
          },
          problems);
}

// Where a job's run folder is beside a database that moved with its runs
// folder (exec/executor.h runs_root_for, run_dir_for: sharded or flat).
bool run_folder_beside(const fs::path& db_file, const std::string& hash) {
  std::error_code ec;
  const auto abs = fs::absolute(db_file, ec);
  const auto root = abs.parent_path() / (abs.filename().string() + ".runs");
  return (hash.size() > 2 && fs::is_directory(root / hash.substr(0, 2) / hash, ec)) || fs::is_directory(root / hash, ec);
}

void check_gridfree_invariants(Database& db, const fs::path& db_file, std::vector<std::string>& problems) {
  collect_problems(db,
          "SELECT j.id, j.job_hash, COALESCE(r.status, '') FROM jobs j LEFT JOIN results r ON r.job_id = j.id "
          "WHERE j.status = 'done' AND (r.job_id IS NULL OR r.status <> 'converged') ORDER BY j.id",
          [](const Statement& st) {
            const std::string r = st.as_text(2);
            return job_label(st) + " is done but " +
                   (r.empty() ? std::string("has no result") : "its result is '" + r + "', not converged");
          },
          problems);
  collect_problems(db,
          "SELECT se.id, se.case_name, st.name FROM series se JOIN studies st ON st.id = se.study_id "
          "WHERE NOT EXISTS (SELECT 1 FROM study_jobs sj WHERE sj.series_id = se.id) ORDER BY se.id",
          [](const Statement& st) {
            return "series " + std::to_string(st.as_int(0)) + " (" + st.as_text(1) + ", study " + st.as_text(2) +
                   ") has no jobs";
          },
          problems);
  collect_problems(db,
          "SELECT sj.job_id, sj.series_id, sj.study_id, se.study_id FROM study_jobs sj "
          "JOIN series se ON se.id = sj.series_id WHERE se.study_id <> sj.study_id ORDER BY sj.series_id, sj.job_id",
          [](const Statement& st) {
            return "the link of job " + std::to_string(st.as_int(0)) + " to series " + std::to_string(st.as_int(1)) +
                   " names study " + std::to_string(st.as_int(2)) + ", but the series belongs to study " +
                   std::to_string(st.as_int(3));
          },
          problems);
  collect_problems(db,
          "SELECT se.id, se.case_name, COUNT(*) FROM series se JOIN study_jobs sj ON sj.series_id = se.id "
          "JOIN jobs j ON j.id = sj.job_id WHERE se.status = 'done' AND j.status IN ('queued','running') "
          "GROUP BY se.id ORDER BY se.id",
          [](const Statement& st) {
            return "series " + std::to_string(st.as_int(0)) + " (" + st.as_text(1) + ") is done but " +
                   std::to_string(st.as_int(2)) + " of its jobs are queued or running";
          },
          problems);
  auto st = db.prepare(
      "SELECT id, job_hash, result_path FROM jobs WHERE status = 'done' AND COALESCE(result_path, '') <> '' "
      "ORDER BY id");
  long long missing = 0;
  while (st.step()) {
    const fs::path folder = fs::path(st.as_text(2)).parent_path();
    std::error_code ec;
    if (fs::is_directory(folder, ec) || run_folder_beside(db_file, st.as_text(1))) continue;
    if (++missing <= kDbCheckMaxListed)
      problems.push_back(job_label(st) + " is done but its run folder " + folder.string() + " does not exist");
  }
  if (missing > kDbCheckMaxListed)
    problems.push_back("... and " + std::to_string(missing - kDbCheckMaxListed) + " more like the one above");
}

}  // namespace

DbCheckReport check_database(const fs::path& file) {
  check_database_file(file, false);
  DbCheckReport out;
  try {
    Database db(file, false);
    out.schema_version = schema_version(db);
    // A newer schema's invariants are not this program's to judge.
    if (out.schema_version > kSchemaVersion)
      throw InputError("--db", newer_schema_message(db, out.schema_version, kSchemaVersion));
    check_sqlite_integrity(db, out.problems);
    if (out.schema_version < 1) {
      out.problems.push_back("schema version 0: no gridfree tables (an empty SQLite database)");
      return out;
    }
    check_gridfree_invariants(db, file, out.problems);
    out.studies = count_rows(db, "SELECT COUNT(*) FROM studies");
    out.jobs = count_rows(db, "SELECT COUNT(*) FROM jobs");
    out.results = count_rows(db, "SELECT COUNT(*) FROM results");
  } catch (const SqliteError& e) {
    if (busy_code(e.code())) throw;
    out.problems.push_back(std::string("SQLite cannot read the file: ") + sqlite3_errstr(e.code()));
  }
  return out;
}

}  // namespace gridfree
