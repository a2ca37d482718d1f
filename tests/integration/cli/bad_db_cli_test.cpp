// SPDX-License-Identifier: GPL-3.0-or-later
// Every way a --db can be wrong is the user's input, not a bug
// (store/database_file.h, docs/DATABASE.md "When --db is wrong"): exit 2,
// a message naming the path and the problem, never "internal", and the
// file left as it was. Also a --timeout that is neither seconds > 0 nor "none" refused naming the flag.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"

namespace {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `gridfree args` in dir: exit 2, stderr naming every one of `words`, no "internal".
void expect_refused(const fs::path& dir, const std::string& args, std::initializer_list<std::string> words) {
  const auto r = ts::gridfree_in(dir, args);
  EXPECT_EQ(r.exit_code, 2) << args << '\n' << r.err;
  EXPECT_EQ(r.err.find("internal"), std::string::npos) << r.err;
  for (const auto& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << "'" << w << "' in:\n" << r.err;
}

// A database with one finished 3-job study, closed (its WAL checkpointed).
fs::path finished_database(const fs::path& dir) {
  const auto study = ts::write_ok_study(dir, "done");
  const auto r = ts::gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 1 --db g.sqlite");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return dir / "g.sqlite";
}

TEST(BadDb, ADirectoryIsNamed) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "directory");
  fs::create_directories(dir / "folder.sqlite");
  const auto study = ts::write_ok_study(dir, "s");
  expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db folder.sqlite",
                 {"--db", "folder.sqlite", "is a directory"});
  expect_refused(dir, "status --db folder.sqlite", {"folder.sqlite", "is a directory"});
  expect_refused(dir, "db check --db folder.sqlite", {"folder.sqlite", "is a directory"});
}

TEST(BadDb, APathInAMissingFolderIsNamed) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "missing_folder");
  const auto study = ts::write_ok_study(dir, "s");
  expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db nowhere/g.sqlite",
                 {"nowhere/g.sqlite", "folder that does not exist"});
  expect_refused(dir, "submit " + ts::shell_quote(study.string()) + " --db nowhere/g.sqlite",
                 {"nowhere/g.sqlite", "folder that does not exist"});
  EXPECT_FALSE(fs::exists(dir / "nowhere"));
}

TEST(BadDb, RandomBytesAreNotADatabase) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "random");
  std::mt19937 rng(53);
  std::string noise(8192, '\0');
  for (auto& c : noise) c = static_cast<char>(rng() & 0xff);
  std::ofstream(dir / "noise.sqlite", std::ios::binary) << noise;
  const auto study = ts::write_ok_study(dir, "s");
  expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db noise.sqlite",
                 {"noise.sqlite", "is not a SQLite database"});
  expect_refused(dir, "status --db noise.sqlite", {"noise.sqlite", "is not a SQLite database"});
  EXPECT_EQ(bytes_of(dir / "noise.sqlite"), noise);
}

TEST(BadDb, TheStudyFileItselfIsNamedAsJson) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "study_file");
  const auto study = ts::write_ok_study(dir, "s");
  const std::string before = bytes_of(study);
  expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db s.json",
                 {"s.json", "is not a SQLite database", "JSON"});
  EXPECT_EQ(bytes_of(study), before);
}

TEST(BadDb, ATruncatedFileIsDamagedAndPointsAtDbCheck) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "truncated");
  const auto db = finished_database(dir);
  ASSERT_FALSE(fs::exists(db.string() + "-wal"));  // checkpointed at close: every page is in the file
  const std::string whole = bytes_of(db);
  ASSERT_GT(whole.size(), 8192u);
  std::ofstream(db, std::ios::binary | std::ios::trunc) << whole.substr(0, 8192);  // pages 1-2 of 4096 bytes
  expect_refused(dir, "status --db g.sqlite", {"g.sqlite", "damaged", "gridfree db check"});
  const auto check = ts::gridfree_in(dir, "db check --db g.sqlite");
  EXPECT_EQ(check.exit_code, 1) << check.out << check.err;
  EXPECT_NE(check.out.find("Recovery"), std::string::npos) << check.out;
}

TEST(BadDb, ACorruptedPageIsDamagedAndDbCheckListsIt) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "corrupted_page");
  const auto db = finished_database(dir);
  const int page = std::stoi(ts::sqlite_query(db, "SELECT rootpage FROM sqlite_master WHERE name = 'jobs'"));
  const int page_size = std::stoi(ts::sqlite_query(db, "PRAGMA page_size"));
  std::string bytes = bytes_of(db);
  // The b-tree page header of the jobs table: its type byte and cell count.
  for (int i = 0; i < 8; ++i) bytes[static_cast<std::size_t>((page - 1) * page_size + i)] = '\x7f';
  std::ofstream(db, std::ios::binary | std::ios::trunc) << bytes;
  expect_refused(dir, "status --db g.sqlite", {"g.sqlite", "damaged", "gridfree db check"});
  const auto check = ts::gridfree_in(dir, "db check --db g.sqlite");
  EXPECT_EQ(check.exit_code, 1) << check.out << check.err;
  EXPECT_NE(check.out.find("problem"), std::string::npos) << check.out;
  EXPECT_EQ(check.err.find("internal"), std::string::npos) << check.err;
}

TEST(BadDb, ANewerSchemaSaysWhoWroteItAndThatThisOneIsOlder) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "newer");
  const auto db = finished_database(dir);
  ts::sqlite_query(db, "INSERT INTO events(kind, message) VALUES ('schema', "
                       "'schema version 99 by gridfree 9.9.9 (future), from version 13'); PRAGMA user_version = 99");
  const auto study = ts::write_ok_study(dir, "another");
  expect_refused(dir, "status --db g.sqlite",
                 {"g.sqlite", "schema version 99", "gridfree 9.9.9 (future)", "is older", "up to 13"});
  expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db g.sqlite", {"schema version 99"});
  EXPECT_EQ(ts::sqlite_query(db, "PRAGMA user_version"), "99");
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM studies"), "1");
}

TEST(BadDb, EachMigrationRecordsTheGridfreeThatMadeIt) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "schema_event");
  const auto db = finished_database(dir);
  EXPECT_EQ(ts::sqlite_query(db, "SELECT message LIKE 'schema version 13 by gridfree %, from version 0' FROM events "
                                 "WHERE kind = 'schema'"),
            "1");
}

TEST(BadDb, ATimeoutNotPositiveIsRefusedNamingTheFlag) {
  const auto dir = ts::fresh_scratch_dir("bad_db", "timeout");
  const auto study = ts::write_ok_study(dir, "s");
  for (const char* t : {"-1", "-5", "-0.5", "0", "nan", "inf", "10s", "never"}) {
    SCOPED_TRACE(t);
    expect_refused(dir, "run " + ts::shell_quote(study.string()) + " --db g.sqlite --timeout " + t, {"--timeout"});
    expect_refused(dir, "daemon --db g.sqlite --timeout " + std::string(t), {"--timeout"});
  }
  EXPECT_FALSE(fs::exists(dir / "g.sqlite"));  // refused before the database was opened
  // The two accepted forms: seconds > 0, and "none".
  for (const char* t : {"none", "3600"}) {
    const auto r = ts::gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 1 --db ok.sqlite --timeout " + t);
    EXPECT_EQ(r.exit_code, 0) << t << '\n' << r.err;
  }
}

}  // namespace
