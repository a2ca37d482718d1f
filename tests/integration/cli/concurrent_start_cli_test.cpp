// SPDX-License-Identifier: GPL-3.0-or-later
// Many `gridfree run`s started at once on a database file that does not
// exist yet (docs/DATABASE.md "Many processes at once"): creating the file,
// switching it to WAL and making the tables happen under one exclusive lock
// the others wait for (store/journal_mode.h, store/schema.cpp), so every
// process succeeds. Eight processes a round: two different studies, each
// started four times (the same study several times over). Every job is
// solved once, every result stored once.
// GRIDFREE_TEST_START_ROUNDS sets the number of rounds (default 3; the
// rounds measured by hand are in docs/DATABASE.md).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "test_files.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

int start_rounds() {
  const char* env = std::getenv("GRIDFREE_TEST_START_ROUNDS");
  return env != nullptr && std::atoi(env) > 0 ? std::atoi(env) : 3;
}

// Another study over the ok case: Δ* 5 (first's job too), 3.6 and 2.8.
fs::path second_study(const fs::path& dir) {
  const auto file = ts::write_ok_study(dir, "second");
  auto doc = nlohmann::json::parse(std::ifstream(file));
  doc["grids"] = {{"delta_star", {5.0, 3.6, 2.8}}};
  std::ofstream(file) << doc.dump(2);
  return file;
}

TEST(ConcurrentStart, EightRunsOnANewDatabaseAllSucceed) {
  const int rounds = start_rounds();
  constexpr int kProcesses = 8;
  for (int round = 0; round < rounds; ++round) {
    SCOPED_TRACE("round " + std::to_string(round + 1) + " of " + std::to_string(rounds));
    const auto dir = ts::fresh_scratch_dir("concurrent_start", "round" + std::to_string(round));
    const auto first = ts::write_ok_study(dir, "first");  // Δ* 5, 4, 3.3
    const auto second = second_study(dir);                 // Δ* 5, 3.6, 2.8: one job shared
    std::vector<pid_t> pids;
    for (int i = 0; i < kProcesses; ++i) {
      const auto& study = i % 2 == 0 ? first : second;
      pids.push_back(ts::spawn_gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 1 --db g.sqlite", "0",
                                           "p" + std::to_string(i) + ".log"));
    }
    for (int i = 0; i < kProcesses; ++i) {
      const std::string log = "p" + std::to_string(i) + ".log";
      EXPECT_EQ(ts::exit_code_within(pids[static_cast<std::size_t>(i)], 180), 0) << ts::slurp(dir / log);
      EXPECT_EQ(ts::slurp(dir / log).find("internal"), std::string::npos) << ts::slurp(dir / log);
    }
    const auto db = dir / "g.sqlite";
    EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM studies WHERE status = 'done'"), "2");
    EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*), COUNT(DISTINCT job_id) FROM results"), "5|5");
    EXPECT_EQ(ts::sqlite_query(db, "SELECT SUM(attempts) FROM jobs"), "5");  // none solved twice
    EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM events WHERE kind = 'schema'"), "1");  // made once
    EXPECT_EQ(ts::sqlite_query(db, "PRAGMA integrity_check"), "ok");
    if (::testing::Test::HasFailure()) break;
  }
}

}  // namespace
