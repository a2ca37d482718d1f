// SPDX-License-Identifier: GPL-3.0-or-later
// docs/DATABASE.md describes the schema users query: every table and view
// of a database at the current schema version has exactly one entry
// (**name** at the start of a line), and that entry names every one of its
// columns in backquotes, so a column added to the schema without its
// description (or a second, diverging entry) fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.h"
#include "store/schema.h"
#include "store/sqlite.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

std::string database_doc() {
  std::ifstream in(fs::path(GRIDFREE_SOURCE_DIR) / "docs/DATABASE.md");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> column_of_rows(Database& db, const std::string& sql, int col) {
  auto st = db.prepare(sql);
  std::vector<std::string> out;
  while (st.step()) out.push_back(st.as_text(col));
  return out;
}

// Offsets of the lines that start with "**name**".
std::vector<std::size_t> entries(const std::string& doc, const std::string& name) {
  std::vector<std::size_t> at;
  const std::string head = "**" + name + "**";
  for (std::size_t p = doc.find(head); p != std::string::npos; p = doc.find(head, p + 1))
    if (p == 0 || doc[p - 1] == '\n') at.push_back(p);
  return at;
}

// The entry's text: to the next line that opens another entry or a section.
std::string entry_text(const std::string& doc, std::size_t at) {
  std::size_t end = doc.size();
  for (const char* next : {"\n**", "\n## "}) end = std::min(end, doc.find(next, at + 2));
  return doc.substr(at, end - at);
}

TEST(DatabaseDoc, EveryTableAndViewHasOneEntryNamingEachOfItsColumns) {
  const auto dir = test_support::fresh_scratch_dir("database_doc_test", "schema");
  Database db(dir / "schema.sqlite", true);
  migrate(db);
  const std::string doc = database_doc();
  ASSERT_FALSE(doc.empty());
  const auto names = column_of_rows(
      db, "SELECT name FROM sqlite_master WHERE type IN ('table', 'view') AND name NOT LIKE 'sqlite_%' ORDER BY name",
      0);
  ASSERT_GE(names.size(), 10u);
  for (const auto& name : names) {
    const auto at = entries(doc, name);
    ASSERT_EQ(at.size(), 1u) << name << ": " << at.size() << " entries in docs/DATABASE.md";
    const std::string text = entry_text(doc, at.front());
    for (const auto& column : column_of_rows(db, "PRAGMA table_info(" + name + ")", 1))
      EXPECT_NE(text.find("`" + column + "`"), std::string::npos)
          << name << "." << column << " is not described in its docs/DATABASE.md entry";
  }
}

}  // namespace
}  // namespace gridfree
