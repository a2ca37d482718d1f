// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree db backup FILE` and `gridfree db vacuum` (docs/DATABASE.md
// "Checking, backing up, compacting").
//
// A backup is SQLite's online backup (sqlite3_backup_*) copying every page
// in one step, that is inside one read transaction of the source: in WAL
// mode a reader sees one committed state and does not stop writers, so the
// copy is consistent while a `run` or `daemon` keeps writing (a `cp` of the
// file alone can miss the pages still in the -wal file). The copy is
// written to FILE.part and renamed to FILE when complete; it is a single
// file (no -wal) that opens as it is, so it restores with `cp`.
//
// VACUUM rewrites the file without its free pages, then the WAL is
// checkpointed and truncated. It holds the write lock while it works: a
// running `run`/`daemon` waits for it (up to the busy wait's bound,
// store/busy_wait.h).
#pragma once

#include <cstdint>
#include <filesystem>

namespace gridfree {

struct BackupSummary {
  int pages = 0;
  std::uintmax_t bytes = 0;  // size of the copy
};

// Copies `db` to `copy`, which must not exist yet (its folder must);
// refusals are InputError naming FILE or --db.
BackupSummary backup_database(const std::filesystem::path& db, const std::filesystem::path& copy);

struct VacuumSummary {
  std::uintmax_t bytes_before = 0, bytes_after = 0;  // the file plus its -wal
};

VacuumSummary vacuum_database(const std::filesystem::path& db);

}  // namespace gridfree
