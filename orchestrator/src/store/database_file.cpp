// SPDX-License-Identifier: GPL-3.0-or-later
// Problems with the file a --db names (store/database_file.h).
#include "store/database_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>

#include "core/version.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 16> kSqliteHeader = {'S', 'Q', 'L', 'i', 't', 'e', ' ', 'f',
                                                'o', 'r', 'm', 'a', 't', ' ', '3', '\0'};

[[noreturn]] void refuse_db_file(const fs::path& file, const std::string& problem) {
  throw InputError("--db", "'" + file.string() + "' " + problem);
}

// What a file that is not a SQLite database seems to be, from its start.
std::string not_a_database_words(const std::string& start) {
  std::size_t i = 0;
  while (i < start.size() && std::isspace(static_cast<unsigned char>(start[i])) != 0) ++i;
  if (i < start.size() && (start[i] == '{' || start[i] == '['))
    return "is not a SQLite database: it is a text file that starts like JSON (a study file? the database is "
           "the file given to --db, the study the file before it)";
  return "is not a SQLite database (its first bytes are not SQLite's header \"SQLite format 3\"): give the "
         "database gridfree wrote, or a new file name";
}

}  // namespace

void check_database_file(const fs::path& file, bool create) {
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (fs::is_directory(status)) refuse_db_file(file, "is a directory, not a database file: give a file name, e.g. " +
                                                 (file / "gridfree.sqlite").string());
  if (!fs::exists(status)) {
    const auto folder = fs::absolute(file, ec).parent_path();
    if (!fs::is_directory(folder, ec))
      refuse_db_file(file, "is in a folder that does not exist (" + folder.string() +
                       "): gridfree creates the database file, not its folders");
    if (!create) refuse_db_file(file, "does not exist: no database at that path (submit or run a study first)");
    return;
  }
  if (!fs::is_regular_file(status)) refuse_db_file(file, "is not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in) refuse_db_file(file, "cannot be read (permission denied?)");
  std::string start(kSqliteHeader.size(), '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(in.gcount()));
  if (start.empty()) return;  // an empty file: SQLite makes it a new database
  if (start.size() < kSqliteHeader.size() || !std::equal(kSqliteHeader.begin(), kSqliteHeader.end(), start.begin()))
    refuse_db_file(file, not_a_database_words(start));
}

std::optional<InputError> database_file_error(const fs::path& file, const SqliteError& e) {
  const int code = e.code() & 0xff;
  const std::string name = "'" + file.string() + "' ";
  if (damaged_code(code)) return InputError("--db", e.what());  // the sentence of store/sqlite.cpp, with the advice
  if (code == SQLITE_CANTOPEN || code == SQLITE_PERM)
    return InputError("--db", name + "cannot be opened (" + e.what() + ")");
  if (code == SQLITE_READONLY)
    return InputError("--db", name + "cannot be written (" + e.what() + "): gridfree writes the file and, beside "
                                     "it, " + file.filename().string() + "-wal and -shm; the file and its folder "
                                     "must be writable");
  return std::nullopt;
}

std::string newer_schema_message(Database& db, int version, int known) {
  std::string writer;
  try {  // the newer schema may have no such table or row: then the number says it
    auto st = db.prepare("SELECT message FROM events WHERE kind = 'schema' ORDER BY id DESC LIMIT 1");
    // Only a row about this very version names its writer.
    if (st.step() && st.as_text(0).rfind("schema version " + std::to_string(version) + " ", 0) == 0)
      writer = st.as_text(0);
  } catch (const SqliteError&) {
  }
  const char* file = sqlite3_db_filename(db.handle(), "main");
  return std::string("'") + (file != nullptr ? file : "") + "' has schema version " + std::to_string(version) +
         (writer.empty() ? std::string(", written by a newer gridfree") : " (" + writer + ")") + "; this " +
         version_string() + " is older: it knows schema versions up to " + std::to_string(known) +
         " and leaves the file as it is. Use the gridfree that wrote it, or a newer one";
}

}  // namespace gridfree
