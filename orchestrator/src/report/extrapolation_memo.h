// SPDX-License-Identifier: GPL-3.0-or-later
// Extrapolations remembered between report writes.
//
// While series finish, the scheduler rewrites a study's report every few
// seconds; each write extrapolates every series again (report/series_summary.h),
// about 15 ms a series of 18 grids: 40 s a write at 2 700 series, for
// answers that did not change. A memo wraps the report's Extrapolator and
// returns the JSON it returned before for the same (h, f) — the same bits,
// so a changed grid value or a new grid is extrapolated anew. One memo per
// study and extrapolator (its settings are fixed for the study); entries
// not used by the last write are dropped at end_write(), so the memo holds
// at most the extrapolations of two writes. Entries are kept as CBOR (exact
// doubles, about 4 KB a series instead of 40 KB as a json tree: 108 MB at
// 2 700 series) and decoded on a hit (about 20 µs).
#pragma once

#include <cstdint>
#include <string>
#include <vector>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "report/extrapolator.h"

namespace gridfree {

class ExtrapolationMemo {
 public:
  // The memo must outlive the returned function.
  Extrapolator wrap(Extrapolator inner);
  // After a report write: forget what that write did not use.
  void end_write();
  std::size_t size() const { return previous_.size() + current_.size(); }
  long long hits() const { return hits_; }

 private:
  std::unordered_map<std::string, std::vector<std::uint8_t>> previous_, current_;  // input → CBOR
  long long hits_ = 0;
};

}  // namespace gridfree
