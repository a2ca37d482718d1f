// SPDX-License-Identifier: GPL-3.0-or-later
// Prepared statements kept for reuse on one connection, keyed by their SQL
// text. A Statement takes an idle handle for its text (or prepares one) and
// gives it back, reset and with its bindings cleared, when it ends; so a
// statement run once per job is compiled once per connection, not once per
// job (docs/BENCHMARKS.md "Prepared statements kept").
// At most max_texts distinct texts are kept: statements of other texts are
// finalized when they end, so SQL built at run time cannot grow the cache
// without bound. Several handles of one text may be idle at once (a text in
// use twice, nested, prepares a second handle).
#pragma once

#include <sqlite3.h>

#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace gridfree {

class StatementCache {
 public:
  // A handle for a text: `statement` is an idle prepared one, or nullptr
  // (prepare it); `key` names the text's slot, or is nullptr when the cache
  // is full and the handle is to be finalized when it ends.
  struct Taken {
    sqlite3_stmt* statement = nullptr;
    const std::string* key = nullptr;
  };

  static constexpr std::size_t kDefaultMaxTexts = 256;

  explicit StatementCache(std::size_t max_texts = kDefaultMaxTexts) : max_texts_(max_texts) {}
  ~StatementCache() { clear(); }
  StatementCache(const StatementCache&) = delete;
  StatementCache& operator=(const StatementCache&) = delete;

  Taken take(std::string_view sql);
  // Resets the handle and keeps it idle under key (from take()).
  void give(const std::string* key, sqlite3_stmt* statement);
  // Finalizes every idle handle (before the connection closes); keeps the texts.
  void clear();

  std::size_t texts() const;
  std::size_t idle() const;

 private:
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  mutable std::mutex mutex_;
  std::size_t max_texts_;
  std::unordered_map<std::string, std::vector<sqlite3_stmt*>, Hash, std::equal_to<>> idle_;
};

}  // namespace gridfree
