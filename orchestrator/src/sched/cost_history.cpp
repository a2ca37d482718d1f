// SPDX-License-Identifier: GPL-3.0-or-later
// read_cost_history (sched/cost_history.h).
#include "sched/cost_history.h"

#include "store/sqlite.h"

namespace gridfree {

CostHistory read_cost_history(Database& db, bool external_only) {
  CostHistory history;
  // instr(): a cheap filter before the JSON is parsed (an external job's
  // spec names "external"; every candidate is still keyed by its parsed spec).
  auto st = db.prepare(
      std::string("SELECT j.spec_json, r.nx, r.ny, r.nz, r.cpu_s, COALESCE(r.peak_rss_mb, 0) FROM jobs j "
                  "JOIN results r ON r.job_id = j.id "
                  "WHERE r.status = 'converged' AND (r.cpu_s > 0 OR r.peak_rss_mb > 0) AND r.nx > 0 AND r.ny > 0 AND r.nz > 0") +
      (external_only ? " AND instr(j.spec_json, '\"external\"') > 0" : ""));
  while (st.step()) {
    const auto spec = nlohmann::json::parse(st.as_text(0), nullptr, false);
    if (!spec.is_object()) continue;
    const double cells = static_cast<double>(st.as_int(1)) * static_cast<double>(st.as_int(2)) *
                         static_cast<double>(st.as_int(3));
    history[cost_similarity_key(spec)].push_back({cells, st.as_double(4), st.as_double(5)});
  }
  return history;
}

CostHistory read_cost_history(const std::filesystem::path& db_file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(db_file, ec)) return {};
  Database db(db_file, false);
  return read_cost_history(db, false);
}

}  // namespace gridfree
