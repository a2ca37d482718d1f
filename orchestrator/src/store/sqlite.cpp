// SPDX-License-Identifier: GPL-3.0-or-later
// RAII wrappers over sqlite3 (see sqlite.h).
#include "store/sqlite.h"

#include <cstdlib>
#include <cstring>
#include <string>

namespace gridfree {
namespace {

// A busy database after the wait names the process holding it.
std::string busy_message(sqlite3* db) {
  const char* file = db != nullptr ? sqlite3_db_filename(db, "main") : nullptr;
  if (file == nullptr || *file == '\0') return "the database is busy";
  return std::string("the database ") + file + " is still being written by " + database_lock_holder(file) +
         " after the wait for it ended; try again when it has finished";
}

// A damaged file names itself and what to do (docs/DATABASE.md "Recovery").
std::string damaged_message(sqlite3* db, const std::string& sqlite_words) {
  const char* file = db != nullptr ? sqlite3_db_filename(db, "main") : nullptr;
  const std::string name = file != nullptr && *file != '\0' ? file : "the database";
  return "the database " + name + " is damaged (SQLite: " + sqlite_words + "); `gridfree db check --db " + name +
         "` lists what is wrong, docs/DATABASE.md \"Recovery\" says how to save what it holds";
}

[[noreturn]] void fail(sqlite3* db, int rc, const std::string& context) {
  if ((rc & 0xff) == SQLITE_BUSY) throw SqliteError(busy_message(db), rc);
  const std::string words = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  if (damaged_code(rc)) throw SqliteError(damaged_message(db, words), rc);
  throw SqliteError(context + ": " + words, rc);
}

}  // namespace

bool busy_code(int code) { return (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED; }

bool damaged_code(int code) { return (code & 0xff) == SQLITE_CORRUPT || (code & 0xff) == SQLITE_NOTADB; }

Database::Database(const std::filesystem::path& file, bool create, int busy_timeout_ms) {
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0) | SQLITE_OPEN_FULLMUTEX;
  const int rc = sqlite3_open_v2(file.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    std::string msg = "cannot open database " + file.string() + ": " +
                      (db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(rc));
    if (const int e = db_ != nullptr ? sqlite3_system_errno(db_) : 0; e != 0)
      msg += std::string(" (") + std::strerror(e) + ")";
    sqlite3_close(db_);
    db_ = nullptr;
    throw SqliteError(msg, rc);
  }
  busy_ = std::make_unique<BusyWait>();
  busy_->file = file;
  busy_->limit_ms = busy_timeout_ms;
  if (const char* env = std::getenv("GRIDFREE_DB_WAIT_S"); env != nullptr && std::atoi(env) > 0)
    busy_->limit_ms = std::atoi(env) * 1000;
  sqlite3_busy_handler(db_, busy_wait_handler, busy_.get());
  exec("PRAGMA foreign_keys = ON");
}

Database::~Database() {
  statements_.clear();
  sqlite3_close(db_);
}

void Database::exec(std::string_view sql) {
  char* err = nullptr;
  const std::string text(sql);
  const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &err);
  if (rc != SQLITE_OK) {
    std::string msg = err != nullptr ? err : sqlite3_errstr(rc);
    sqlite3_free(err);
    if ((rc & 0xff) == SQLITE_BUSY) throw SqliteError(busy_message(db_), rc);
    if (damaged_code(rc)) throw SqliteError(damaged_message(db_, msg), rc);
    throw SqliteError("sqlite: " + msg + " (in: " + text.substr(0, 80) + ")", rc);
  }
}

bool Database::wait_busy(int attempt) { return busy_wait_handler(busy_.get(), attempt) != 0; }

Statement Database::prepare(std::string_view sql) { return Statement(db_, statements_, sql); }

Statement::Statement(sqlite3* db, StatementCache& cache, std::string_view sql) : db_(db), cache_(&cache) {
  const StatementCache::Taken taken = cache.take(sql);
  key_ = taken.key;
  st_ = taken.statement;
  if (st_ != nullptr) return;
  const int rc = sqlite3_prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &st_, nullptr);
  if (rc != SQLITE_OK) {
    sqlite3_finalize(st_);
    fail(db, rc, "prepare '" + std::string(sql.substr(0, 80)) + "'");
  }
}

Statement::~Statement() {
  if (st_ == nullptr) return;
  if (key_ != nullptr)
    cache_->give(key_, st_);
  else
    sqlite3_finalize(st_);
}

Statement& Statement::bind(int i, long long v) {
  if (const int rc = sqlite3_bind_int64(st_, i, v); rc != SQLITE_OK) fail(db_, rc, "bind");
  return *this;
}
Statement& Statement::bind(int i, double v) {
  if (const int rc = sqlite3_bind_double(st_, i, v); rc != SQLITE_OK) fail(db_, rc, "bind");
  return *this;
}
Statement& Statement::bind(int i, const std::string& v) {
  const int rc = sqlite3_bind_text(st_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
  if (rc != SQLITE_OK) fail(db_, rc, "bind");
  return *this;
}
Statement& Statement::bind(int i, std::nullopt_t) {
  if (const int rc = sqlite3_bind_null(st_, i); rc != SQLITE_OK) fail(db_, rc, "bind");
  return *this;
}
Statement& Statement::bind(int i, const std::optional<double>& v) {
  return v ? bind(i, *v) : bind(i, std::nullopt);
}
Statement& Statement::bind(int i, const std::optional<long long>& v) {
  return v ? bind(i, *v) : bind(i, std::nullopt);
}

Statement& Statement::bind(int i, const std::optional<std::string>& v) {
  return v ? bind(i, *v) : bind(i, std::nullopt);
}

bool Statement::step() {
  const int rc = sqlite3_step(st_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  fail(db_, rc, "step");
}

void Statement::run() {
  while (step()) {
  }
}

void Statement::reset() {
  sqlite3_reset(st_);
  sqlite3_clear_bindings(st_);
}

std::string Statement::as_text(int col) const {
  const auto* p = sqlite3_column_text(st_, col);
  if (p == nullptr) return {};
  return std::string(reinterpret_cast<const char*>(p), static_cast<std::size_t>(sqlite3_column_bytes(st_, col)));
}

std::optional<double> Statement::as_opt_double(int col) const {
  if (is_null(col)) return std::nullopt;
  return as_double(col);
}

Transaction::Transaction(Database& db, Begin begin) : db_(db) {
  db_.exec(begin == Begin::kExclusive ? "BEGIN EXCLUSIVE" : begin == Begin::kImmediate ? "BEGIN IMMEDIATE" : "BEGIN");
}

Transaction::~Transaction() {
  if (!done_) {
    try {
      db_.exec("ROLLBACK");
    } catch (...) {
    }
  }
}

void Transaction::commit() {
  db_.exec("COMMIT");
  done_ = true;
}

}  // namespace gridfree
