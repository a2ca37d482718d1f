// SPDX-License-Identifier: GPL-3.0-or-later
// One-value queries and result rows for the store tests.
#pragma once

#include <string>

#include "store/sqlite.h"
#include "store/store.h"

namespace gridfree::test_support {

// The first column of the first row of `sql`, as an integer or as text.
inline long long scalar(Database& db, const std::string& sql) {
  auto st = db.prepare(sql);
  st.step();
  return st.as_int(0);
}
inline long long scalar(Store& store, const std::string& sql) { return scalar(store.db(), sql); }

inline std::string text(Database& db, const std::string& sql) {
  auto st = db.prepare(sql);
  st.step();
  return st.as_text(0);
}
inline std::string text(Store& store, const std::string& sql) { return text(store.db(), sql); }

// A converged result: dp* at Δ*, no result document.
inline ResultRow converged(double dp, double delta_star) {
  ResultRow r;
  r.status = "converged";
  r.dp_star = dp;
  r.delta_star = delta_star;
  r.result_json = "{}";
  return r;
}

}  // namespace gridfree::test_support
