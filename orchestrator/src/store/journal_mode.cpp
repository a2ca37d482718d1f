// SPDX-License-Identifier: GPL-3.0-or-later
// WAL mode, retried while another connection holds the file (store/journal_mode.h).
#include "store/journal_mode.h"

#include <string>

namespace gridfree {

std::string enable_wal(Database& db) {
  for (int attempt = 0;; ++attempt) {
    try {
      auto st = db.prepare("PRAGMA journal_mode = WAL");
      st.step();
      return st.as_text(0);
    } catch (const SqliteError& e) {
      if ((e.code() & 0xff) != SQLITE_BUSY || !db.wait_busy(attempt)) throw;
    }
  }
}

}  // namespace gridfree
