// SPDX-License-Identifier: GPL-3.0-or-later
// The database schema (docs/INTERFACE.md §5 plus bookkeeping columns) and its
// migrations, keyed by PRAGMA user_version.
#pragma once

#include "store/sqlite.h"

namespace gridfree {

inline constexpr int kSchemaVersion = 13;

// Brings the database up to kSchemaVersion (WAL mode, tables, view) in one
// transaction per step. Refuses a database newer than this program.
// `target` below kSchemaVersion stops earlier (tests build old databases).
void migrate(Database& db, int target = kSchemaVersion);

int schema_version(Database& db);

}  // namespace gridfree
