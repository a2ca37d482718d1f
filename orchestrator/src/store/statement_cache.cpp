// SPDX-License-Identifier: GPL-3.0-or-later
// Prepared statements kept for reuse (see statement_cache.h).
#include "store/statement_cache.h"

namespace gridfree {

StatementCache::Taken StatementCache::take(std::string_view sql) {
  const std::lock_guard lock(mutex_);
  auto it = idle_.find(sql);
  if (it == idle_.end()) {
    if (idle_.size() >= max_texts_) return {};
    it = idle_.emplace(std::string(sql), std::vector<sqlite3_stmt*>{}).first;
  }
  Taken taken{nullptr, &it->first};
  if (!it->second.empty()) {
    taken.statement = it->second.back();
    it->second.pop_back();
  }
  return taken;
}

void StatementCache::give(const std::string* key, sqlite3_stmt* statement) {
  sqlite3_reset(statement);  // the error of a failed step was reported by that step
  sqlite3_clear_bindings(statement);
  const std::lock_guard lock(mutex_);
  idle_.find(*key)->second.push_back(statement);
}

void StatementCache::clear() {
  const std::lock_guard lock(mutex_);
  for (auto& [sql, handles] : idle_) {  // the texts stay: a live Statement names its slot
    for (sqlite3_stmt* st : handles) sqlite3_finalize(st);
    handles.clear();
  }
}

std::size_t StatementCache::texts() const {
  const std::lock_guard lock(mutex_);
  return idle_.size();
}

std::size_t StatementCache::idle() const {
  const std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const auto& [sql, handles] : idle_) n += handles.size();
  return n;
}

}  // namespace gridfree
