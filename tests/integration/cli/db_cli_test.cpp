// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree db check | backup | vacuum (store/db_check.h, store/db_backup.h;
// docs/DATABASE.md "Checking, backing up, compacting"): check passes a
// database a run wrote and lists each broken invariant (exit 1); a backup
// taken while a daemon writes restores with cp to a database check passes
// and that resumes the study without rerunning the jobs finished in it.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "fake_worker.h"
#include "quickstart_study.h"
#include "run_command.h"
#include "scratch_dir.h"
#include "wait_until.h"

namespace {

namespace fs = std::filesystem;
namespace ts = gridfree::test_support;

// Four series on ten grids: 40 jobs, time enough to back up mid-run.
fs::path write_long_study(const fs::path& dir) {
  const auto file = ts::write_ok_study(dir, "long");
  auto doc = nlohmann::json::parse(std::ifstream(file));
  doc["factors"] = {{"convection", {"superbee", "fou"}}, {"fwhm_dp", {6}}, {"drag", {"bvk", "wen_yu"}}};
  doc["grids"] = {{"delta_star", {5.0, 4.6, 4.2, 3.9, 3.6, 3.3, 3.1, 2.9, 2.7, 2.5}}};
  std::ofstream(file) << doc.dump(2);
  return file;
}

fs::path checked_run(const fs::path& dir) {
  const auto study = ts::write_ok_study(dir, "small");
  const auto r = ts::gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 1 --db g.sqlite");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return dir / "g.sqlite";
}

std::set<std::string> lines_of(const std::string& text) {
  std::set<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.insert(line);
  return out;
}

TEST(DbCommands, CheckPassesWhatARunWrote) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "check_sound");
  checked_run(dir);
  const auto r = ts::gridfree_in(dir, "db check --db g.sqlite");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("sound (schema version 13; 1 studies, 3 jobs, 3 results)"), std::string::npos) << r.out;
}

// result_path is absolute; a database moved together with its runs folder
// finds the run folders beside it.
TEST(DbCommands, ADatabaseMovedWithItsRunsFolderIsSound) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "moved");
  checked_run(dir);
  fs::create_directories(dir / "moved");
  fs::rename(dir / "g.sqlite", dir / "moved/g.sqlite");
  fs::rename(dir / "g.sqlite.runs", dir / "moved/g.sqlite.runs");
  const auto r = ts::gridfree_in(dir, "db check --db moved/g.sqlite");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  fs::remove_all(dir / "moved/g.sqlite.runs");
  EXPECT_EQ(ts::gridfree_in(dir, "db check --db moved/g.sqlite").exit_code, 1);
}

TEST(DbCommands, CheckListsEachBrokenInvariant) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "check_broken");
  const auto db = checked_run(dir);
  const std::string first = ts::sqlite_query(db, "SELECT MIN(id) FROM jobs");
  const std::string last = ts::sqlite_query(db, "SELECT MAX(id) FROM jobs");
  // A done job without its result; another whose run folder is gone; a
  // series done while its job is queued again; a link naming another study.
  ts::sqlite_query(db, "DELETE FROM results WHERE job_id = " + first);
  fs::remove_all(fs::path(ts::sqlite_query(db, "SELECT result_path FROM jobs WHERE id = " + last)).parent_path());
  ts::sqlite_query(db, "INSERT INTO studies(name, definition_json) VALUES ('other', '{}')");
  const std::string middle = ts::sqlite_query(db, "SELECT id FROM jobs WHERE id NOT IN (" + first + ", " + last + ")");
  ts::sqlite_query(db, "UPDATE jobs SET status = 'queued' WHERE id = " + middle +
                           "; UPDATE study_jobs SET study_id = (SELECT id FROM studies WHERE name = 'other') "
                           "WHERE job_id = " + middle);
  const auto r = ts::gridfree_in(dir, "db check --db g.sqlite");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("4 problem(s) found"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("job " + first + " ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("is done but has no result"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("job " + last + " (") , std::string::npos) << r.out;
  EXPECT_NE(r.out.find("its run folder"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("is done but 1 of its jobs are queued or running"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("but the series belongs to study"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Recovery"), std::string::npos) << r.out;
}

TEST(DbCommands, ABackupTakenWhileADaemonWritesRestoresAndResumes) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "backup");
  const auto study = write_long_study(dir);
  const auto db = dir / "g.sqlite";
  ASSERT_EQ(ts::gridfree_in(dir, "submit " + ts::shell_quote(study.string()) + " --db g.sqlite").exit_code, 0);
  const pid_t daemon = ts::spawn_gridfree_in(dir, "daemon -j 2 --db g.sqlite", "0.2", "daemon.log");
  ASSERT_TRUE(ts::wait_until([&] { return ts::sqlite_int(db, "SELECT COUNT(*) FROM results") >= 6; }, 60));
  const auto backup = ts::gridfree_in(dir, "db backup copy.sqlite --db g.sqlite");
  const int results_after = ts::sqlite_int(db, "SELECT COUNT(*) FROM results");
  kill(daemon, SIGTERM);
  EXPECT_EQ(ts::exit_code_within(daemon, 60), 0);
  ASSERT_EQ(backup.exit_code, 0) << backup.out << backup.err;
  EXPECT_NE(backup.out.find("backed up g.sqlite to copy.sqlite"), std::string::npos) << backup.out;
  EXPECT_FALSE(fs::exists(dir / "copy.sqlite-wal"));  // one file: restores with cp
  const int done_in_copy = ts::sqlite_int(dir / "copy.sqlite", "SELECT COUNT(*) FROM jobs WHERE status = 'done'");
  EXPECT_GE(done_in_copy, 6);
  EXPECT_LT(done_in_copy, 40) << "the daemon had finished before the backup: nothing was tested";
  EXPECT_LE(done_in_copy, results_after);
  // Restore: the daemon is stopped; the copy replaces the file, its -wal and -shm removed.
  for (const char* suffix : {"-wal", "-shm"}) fs::remove(db.string() + suffix);
  fs::copy_file(dir / "copy.sqlite", db, fs::copy_options::overwrite_existing);
  const auto check = ts::gridfree_in(dir, "db check --db g.sqlite");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  const std::string done_before =
      ts::sqlite_query(db, "SELECT j.id || ' ' || j.finished_at || ' ' || r.recorded_at FROM jobs j "
                           "JOIN results r ON r.job_id = j.id WHERE j.status = 'done' ORDER BY j.id");
  const std::string done_dirs = ts::sqlite_query(
      db, "SELECT substr(result_path, 1, length(result_path) - length('/result.json')) FROM jobs WHERE status = 'done' ORDER BY id");
  // Resume: the jobs done in the copy are not solved again (the fake
  // worker logs every solve's run folder).
  const auto log = dir / "solves.log";
  const auto resumed = ts::gridfree_in(dir, "run " + ts::shell_quote(study.string()) + " -j 2 --db g.sqlite",
                                       "GRIDFREE_FAKE_LOG=" + ts::shell_quote(log.string()));
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(ts::sqlite_query(db, "SELECT COUNT(*) FROM jobs WHERE status = 'done'"), "40");
  std::ifstream in(log);
  const std::string solved((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // At most the others (one running at the backup may have left its result, which is adopted).
  EXPECT_LE(static_cast<int>(lines_of(solved).size()), 40 - done_in_copy) << solved;
  for (const auto& folder : lines_of(done_dirs))
    EXPECT_EQ(solved.find(folder), std::string::npos) << folder << " solved again:\n" << solved;
  const std::string done_after =
      ts::sqlite_query(db, "SELECT j.id || ' ' || j.finished_at || ' ' || r.recorded_at FROM jobs j "
                           "JOIN results r ON r.job_id = j.id ORDER BY j.id");
  for (const auto& row : lines_of(done_before)) EXPECT_NE(done_after.find(row), std::string::npos) << row;
  EXPECT_EQ(ts::gridfree_in(dir, "db check --db g.sqlite").exit_code, 0);
}

TEST(DbCommands, BackupWritesANewFileOnly) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "backup_exists");
  checked_run(dir);
  std::ofstream(dir / "taken.sqlite") << "keep me";
  const auto r = ts::gridfree_in(dir, "db backup taken.sqlite --db g.sqlite");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("'taken.sqlite' exists"), std::string::npos) << r.err;
  std::ifstream in(dir / "taken.sqlite");
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), "keep me");
  const auto missing = ts::gridfree_in(dir, "db backup x.sqlite --db nothing.sqlite");
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "x.sqlite"));
}

TEST(DbCommands, VacuumKeepsEveryRowAndTheFileSound) {
  const auto dir = ts::fresh_scratch_dir("db_cli", "vacuum");
  const auto db = checked_run(dir);
  const std::string before = ts::sqlite_query(db, "SELECT job_hash, status FROM jobs ORDER BY job_hash");
  ts::sqlite_query(db, "CREATE TABLE padding(x); INSERT INTO padding WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL "
                       "SELECT i + 1 FROM n WHERE i < 2000) SELECT randomblob(500) FROM n; DROP TABLE padding");
  const auto size_before = fs::file_size(db);
  const auto r = ts::gridfree_in(dir, "db vacuum --db g.sqlite");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("vacuumed g.sqlite"), std::string::npos) << r.out;
  EXPECT_LT(fs::file_size(db), size_before / 4);  // the ~1 MB of freed pages gone
  EXPECT_EQ(ts::sqlite_query(db, "SELECT job_hash, status FROM jobs ORDER BY job_hash"), before);
  EXPECT_EQ(ts::gridfree_in(dir, "db check --db g.sqlite").exit_code, 0);
}

}  // namespace
