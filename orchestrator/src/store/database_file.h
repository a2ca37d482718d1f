// SPDX-License-Identifier: GPL-3.0-or-later
// What can be wrong with the file a `--db` names, in the user's words
// (docs/DATABASE.md "When --db is wrong"). Each is the user's input, not a
// bug: InputError("--db", sentence naming the path and what to do), exit 2.
//
//   before SQLite opens it (check_database_file):
//     a directory; a path in a folder that does not exist; a file that is
//     not a SQLite database (its first 16 bytes are not SQLite's header:
//     random bytes, a study's JSON file)
//   from what SQLite said while opening it (database_file_error):
//     damaged (SQLITE_CORRUPT, SQLITE_NOTADB: a truncated file, a
//     corrupted page) -> `gridfree db check` and the Recovery section;
//     cannot be opened or written (SQLITE_CANTOPEN, SQLITE_READONLY,
//     SQLITE_PERM)
//   from its schema (newer_schema_message): written by a newer gridfree.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "core/input_error.h"
#include "store/sqlite.h"

namespace gridfree {

// Throws InputError("--db", ...) when `file` cannot be a database: a
// directory, in a missing folder, or not a SQLite file. A missing file is
// a problem only when !create.
void check_database_file(const std::filesystem::path& file, bool create);

// The InputError for an error SQLite raised while opening or migrating
// `file`, or nullopt when the error is not about the file (a bug, a busy
// database).
std::optional<InputError> database_file_error(const std::filesystem::path& file, const SqliteError& e);

// "… has schema version 99, written by gridfree 0.3.0 (abc1234); this gridfree
// (…) is older: it knows schema versions up to 12 …" for a file whose
// user_version is `version` (> kSchemaVersion). The writer is read from the
// file's last `schema` event when it has one.
std::string newer_schema_message(Database& db, int version, int known);

}  // namespace gridfree
