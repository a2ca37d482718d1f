// SPDX-License-Identifier: GPL-3.0-or-later
// Waiting for a database another process is writing to.
//
// SQLite in WAL mode lets readers run beside one writer; a second writer
// (another `gridfree run`, `daemon`, `submit`) gets SQLITE_BUSY. Instead of
// failing, a connection waits with growing sleeps (1 ms doubling to 100 ms)
// for up to a bound, and after two seconds says once on stderr who holds the
// lock: the process that holds the WAL write lock byte of the "-shm" file,
// found with fcntl(F_GETLK), with its command line. After the bound the
// statement fails with SQLITE_BUSY and a message naming the holder.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

namespace gridfree {

// Default bound on the wait for a busy database (docs/LIMITS.md); the
// environment variable GRIDFREE_DB_WAIT_S overrides it (seconds).
inline constexpr int kDefaultBusyWaitMs = 120000;

struct BusyWait {
  std::filesystem::path file;
  int limit_ms = kDefaultBusyWaitMs;
  std::chrono::steady_clock::time_point since{};
  bool announced = false;
};

// sqlite3_busy_handler callback; `state` is a BusyWait. Returns non-zero to retry.
int busy_wait_handler(void* state, int attempt);

// "pid 1234 (gridfree run study.json)" for the process holding the write
// lock of `db_file`, or "another process" when it cannot be found.
std::string database_lock_holder(const std::filesystem::path& db_file);

}  // namespace gridfree
