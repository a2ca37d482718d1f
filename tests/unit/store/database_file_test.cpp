// SPDX-License-Identifier: GPL-3.0-or-later
// What can be wrong with a --db file (store/database_file.h): each case is
// an InputError at "--db" naming the path and the problem, found before
// SQLite opens the file or from SQLite's error code; a newer schema names
// its writer only from a schema event about that very version.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "scratch_dir.h"
#include "store/database_file.h"
#include "store/schema.h"
#include "store/store.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// `fn` throws InputError at --db whose reason holds `part`.
void expect_db_problem(const std::function<void()>& fn, const std::string& part) {
  try {
    fn();
    FAIL() << "expected an InputError with '" << part << "'";
  } catch (const InputError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].where, "--db");
    EXPECT_NE(e.problems()[0].reason.find(part), std::string::npos) << e.what();
  }
}

TEST(DatabaseFile, EachWrongPathIsNamedBeforeSqliteOpensIt) {
  const auto dir = test_support::fresh_scratch_dir("database_file", "paths");
  fs::create_directories(dir / "folder");
  expect_db_problem([&] { check_database_file(dir / "folder", true); }, "is a directory");
  expect_db_problem([&] { check_database_file(dir / "missing/g.sqlite", true); }, "folder that does not exist");
  expect_db_problem([&] { check_database_file(dir / "absent.sqlite", false); }, "does not exist");
  EXPECT_NO_THROW(check_database_file(dir / "absent.sqlite", true));  // created by SQLite
  std::ofstream(dir / "study.json") << "  {\"name\": \"x\"}";
  expect_db_problem([&] { check_database_file(dir / "study.json", true); }, "starts like JSON");
  std::ofstream(dir / "short.bin") << "SQLite";  // shorter than the header
  expect_db_problem([&] { check_database_file(dir / "short.bin", true); }, "is not a SQLite database");
  std::ofstream(dir / "empty.sqlite") << "";
  EXPECT_NO_THROW(check_database_file(dir / "empty.sqlite", false));  // SQLite makes it a new database
  { Store store(dir / "real.sqlite"); }
  EXPECT_NO_THROW(check_database_file(dir / "real.sqlite", false));
}

TEST(DatabaseFile, SqliteCodesAboutTheFileBecomeInputErrorsOthersDoNot) {
  const fs::path f = "g.sqlite";
  ASSERT_TRUE(database_file_error(f, SqliteError("the database g.sqlite is damaged", SQLITE_CORRUPT)));
  ASSERT_TRUE(database_file_error(f, SqliteError("x", SQLITE_NOTADB)));
  const auto cant = database_file_error(f, SqliteError("unable to open database file", SQLITE_CANTOPEN));
  ASSERT_TRUE(cant);
  EXPECT_NE(std::string(cant->what()).find("'g.sqlite' cannot be opened"), std::string::npos) << cant->what();
  const auto ro = database_file_error(f, SqliteError("attempt to write a readonly database", SQLITE_READONLY));
  ASSERT_TRUE(ro);
  EXPECT_NE(std::string(ro->what()).find("g.sqlite-wal"), std::string::npos) << ro->what();
  EXPECT_FALSE(database_file_error(f, SqliteError("busy", SQLITE_BUSY)));
  EXPECT_FALSE(database_file_error(f, SqliteError("no such table", SQLITE_ERROR)));
}

TEST(DatabaseFile, ANewerSchemaNamesItsWriterOnlyFromAnEventAboutThatVersion) {
  const auto db_file = test_support::fresh_db_path("database_file", "newer");
  { Store store(db_file); }
  Database db(db_file, false);
  const std::string unknown = newer_schema_message(db, kSchemaVersion + 1, kSchemaVersion);
  EXPECT_NE(unknown.find("schema version " + std::to_string(kSchemaVersion + 1) + ", written by a newer gridfree"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("is older: it knows schema versions up to " + std::to_string(kSchemaVersion)),
            std::string::npos);
  const std::string newer = std::to_string(kSchemaVersion + 1);
  db.exec("INSERT INTO events(kind, message) VALUES ('schema', 'schema version " + newer +
          " by gridfree 2.0.0 (abc), from version " + std::to_string(kSchemaVersion) + "')");
  const std::string named = newer_schema_message(db, kSchemaVersion + 1, kSchemaVersion);
  EXPECT_NE(named.find("(schema version " + newer + " by gridfree 2.0.0 (abc), from version " + std::to_string(kSchemaVersion) + ")"), std::string::npos) << named;
  db.exec("PRAGMA user_version = " + newer);
  expect_db_problem([&] { migrate(db); }, "schema version " + newer + " by gridfree 2.0.0");
  EXPECT_EQ(schema_version(db), kSchemaVersion + 1);  // left as it was
}

}  // namespace
}  // namespace gridfree
