// SPDX-License-Identifier: GPL-3.0-or-later
// Switching a database file to WAL mode when several processes open it at
// once (docs/DESIGN.md "Choices", concurrent starts).
//
// SQLite changes a file's journal mode under an exclusive lock it asks for
// from inside a read transaction. When another connection reads at that
// moment (the other process switching the same new file), SQLite returns
// SQLITE_BUSY at once instead of calling the busy handler: waiting while
// holding the read lock could deadlock the two. enable_wal() retries the
// whole statement, its read lock released between tries, with the busy
// handler's sleeps, notice after 2 s and bound (store/busy_wait.h). Once
// the file is in WAL mode (the mode is stored in the file) the statement
// asks for no lock and returns at once.
#pragma once

#include "store/sqlite.h"

namespace gridfree {

// PRAGMA journal_mode = WAL, retried while another connection holds the
// file; throws the busy error after the bound, any other error at once.
// Returns the journal mode in effect ("wal"; "delete" where the file
// system cannot do WAL).
std::string enable_wal(Database& db);

}  // namespace gridfree
