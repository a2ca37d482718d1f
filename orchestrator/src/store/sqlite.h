// SPDX-License-Identifier: GPL-3.0-or-later
// Thin RAII wrappers over the sqlite3 C API: a connection, a prepared
// statement, and a transaction that rolls back unless committed.
// Every failure throws SqliteError with SQLite's message. A connection keeps
// its prepared statements for reuse (store/statement_cache.h).
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <memory>

#include "store/busy_wait.h"
#include "store/statement_cache.h"

namespace gridfree {

class SqliteError : public std::runtime_error {
 public:
  SqliteError(const std::string& what, int code) : std::runtime_error(what), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// SQLITE_BUSY or SQLITE_LOCKED: another process kept the database beyond the wait.
bool busy_code(int code);
// SQLITE_CORRUPT or SQLITE_NOTADB: the file itself is damaged or not a
// database (the user's file, not a bug); the error's message names the
// file and `gridfree db check`.
bool damaged_code(int code);

class Statement;

class Database {
 public:
  // Opens (create = also creates) the file; sets foreign keys and a busy
  // handler that waits up to busy_timeout_ms for another writer
  // (store/busy_wait.h).
  Database(const std::filesystem::path& file, bool create, int busy_timeout_ms = kDefaultBusyWaitMs);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  void exec(std::string_view sql);               // one or more statements, no results
  Statement prepare(std::string_view sql);
  long long last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }
  int changes() const { return sqlite3_changes(db_); }
  sqlite3* handle() { return db_; }
  const StatementCache& statements() const { return statements_; }
  // For a step SQLite refuses with SQLITE_BUSY without calling the busy
  // handler (changing the journal mode while another connection reads):
  // waits as the handler does for its `attempt`-th retry (0 first); false
  // once the bound is reached.
  bool wait_busy(int attempt);

 private:
  sqlite3* db_ = nullptr;
  std::unique_ptr<BusyWait> busy_;
  StatementCache statements_;
};

class Statement {
 public:
  // Takes an idle handle for sql from cache (or prepares one) and gives it
  // back when it ends.
  Statement(sqlite3* db, StatementCache& cache, std::string_view sql);
  ~Statement();
  Statement(Statement&& o) noexcept : db_(o.db_), st_(o.st_), cache_(o.cache_), key_(o.key_) { o.st_ = nullptr; }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement& operator=(Statement&&) = delete;

  Statement& bind(int i, long long v);
  Statement& bind(int i, int v) { return bind(i, static_cast<long long>(v)); }
  Statement& bind(int i, double v);
  Statement& bind(int i, const std::string& v);
  Statement& bind(int i, const char* v) { return bind(i, std::string(v)); }
  Statement& bind(int i, std::nullopt_t);
  Statement& bind(int i, const std::optional<double>& v);
  Statement& bind(int i, const std::optional<long long>& v);
  Statement& bind(int i, const std::optional<std::string>& v);

  // Binds every argument in order (1-based).
  template <class... A>
  Statement& bind_all(const A&... args) {
    int i = 0;
    (bind(++i, args), ...);
    return *this;
  }

  bool step();       // true while a row is available
  void run();        // steps to completion
  void reset();

  bool is_null(int col) const { return sqlite3_column_type(st_, col) == SQLITE_NULL; }
  long long as_int(int col) const { return sqlite3_column_int64(st_, col); }
  double as_double(int col) const { return sqlite3_column_double(st_, col); }
  std::string as_text(int col) const;
  std::optional<double> as_opt_double(int col) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* st_ = nullptr;
  StatementCache* cache_ = nullptr;
  const std::string* key_ = nullptr;  // nullptr: not kept, finalized at the end
};

// BEGIN IMMEDIATE (takes the write lock at once) ... COMMIT; rolls back in
// the destructor if commit() was not reached. kExclusive also keeps readers
// out where the file is not in WAL mode (in WAL mode it is IMMEDIATE).
enum class Begin { kDeferred, kImmediate, kExclusive };

class Transaction {
 public:
  explicit Transaction(Database& db, Begin begin = Begin::kImmediate);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace gridfree
