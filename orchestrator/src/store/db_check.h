// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree db check`: is a database file sound? (docs/DATABASE.md
// "Checking, backing up, compacting"). Reads only; never migrates.
//
//   1. SQLite's own PRAGMA integrity_check (pages, indexes, constraints)
//      and PRAGMA foreign_key_check (rows pointing at missing rows);
//   2. gridfree's invariants, each a query naming the rows that break it:
//      - every done job has its result, and that result converged
//        (done = converged; results.job_id is the key: at most one);
//      - every series has jobs, and each job link (study_jobs) belongs to
//        the study its series belongs to;
//      - no series is done while one of its jobs is queued or running;
//      - the run folder of every done job that recorded one exists (where
//        it recorded it, or in <db>.runs beside a database that moved with
//        its runs folder).
// A file SQLite cannot read at all is one problem naming SQLite's words.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gridfree {

struct DbCheckReport {
  std::vector<std::string> problems;  // one sentence each; empty = sound
  int schema_version = 0;
  long long studies = 0, jobs = 0, results = 0;
  bool clean() const { return problems.empty(); }
};

// Kept per kind of problem; the rest are counted in one more sentence.
inline constexpr int kDbCheckMaxListed = 20;

// Throws InputError("--db") when `file` is not a database at all, or has
// a newer schema (store/database_file.h); anything SQLite cannot read is a
// problem.
DbCheckReport check_database(const std::filesystem::path& file);

}  // namespace gridfree
