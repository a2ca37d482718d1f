// SPDX-License-Identifier: GPL-3.0-or-later
// Concurrent access to one database (store/busy_wait.h): a command meeting
// another process's write transaction waits for it, says on stderr which
// process holds the database, and succeeds once it is free; when the holder
// keeps it beyond the wait (shortened here with GRIDFREE_DB_WAIT_S), the
// command fails with a message naming the holder, not an internal error,
// and the database stays as it was.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
using gridfree::test_support::gridfree_in;
using gridfree::test_support::shell_quote;
using gridfree::test_support::sqlite_query;
using gridfree::test_support::write_ok_study;

// Starts a sqlite3 shell that holds a write transaction on `db` for `seconds`;
// returns once the transaction has begun (the marker file exists).
FILE* hold_write_lock(const fs::path& db, const fs::path& marker, int seconds) {
  const std::string script = "BEGIN IMMEDIATE;\nINSERT INTO studies(name) SELECT NULL WHERE 0;\n.shell touch " +
                             shell_quote(marker.string()) + "\n.shell sleep " + std::to_string(seconds) + "\nCOMMIT;\n";
  FILE* p = popen(("sqlite3 " + shell_quote(db.string()) + " >/dev/null 2>&1").c_str(), "w");
  std::fputs(script.c_str(), p);
  std::fflush(p);
  for (int i = 0; i < 200 && !fs::exists(marker); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  return p;
}

TEST(DbContention, ASecondWriterWaitsAndNamesTheHolder) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("db_contention", "wait");
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(
      gridfree_in(dir, "submit " + shell_quote(write_ok_study(dir, "first").string()) + " --db g.sqlite").exit_code, 0);
  const std::string studies_before = sqlite_query(db, "SELECT COUNT(*) FROM studies");

  FILE* holder = hold_write_lock(db, dir / "held", 4);  // > the 2 s after which the wait is announced
  ASSERT_TRUE(fs::exists(dir / "held"));
  const auto start = std::chrono::steady_clock::now();
  const auto r = gridfree_in(dir, "submit " + shell_quote(write_ok_study(dir, "second").string()) + " --db g.sqlite");
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  pclose(holder);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(waited, 2.0);
  EXPECT_NE(r.err.find("waiting for the database"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sqlite3"), std::string::npos) << "the holder's command line: " << r.err;
  EXPECT_NE(sqlite_query(db, "SELECT COUNT(*) FROM studies"), studies_before);
}

TEST(DbContention, AHolderBeyondTheWaitIsNamedNotAnInternalError) {
  const auto dir = gridfree::test_support::fresh_scratch_dir("db_contention", "bound");
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(
      gridfree_in(dir, "submit " + shell_quote(write_ok_study(dir, "first").string()) + " --db g.sqlite").exit_code, 0);
  const std::string studies_before = sqlite_query(db, "SELECT COUNT(*) FROM studies");
  FILE* holder = hold_write_lock(db, dir / "held", 4);
  const auto r = gridfree_in(dir, "run " + shell_quote(write_ok_study(dir, "second").string()) + " --db g.sqlite",
                             "GRIDFREE_DB_WAIT_S=1");
  pclose(holder);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("still being written by pid"), std::string::npos) << r.err;
  EXPECT_EQ(sqlite_query(db, "SELECT COUNT(*) FROM studies"), studies_before);
}

}  // namespace
