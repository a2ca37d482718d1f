// SPDX-License-Identifier: GPL-3.0-or-later
// Bed summaries per case (see store_beds.h).
#include "store/store_beds.h"

namespace gridfree {

std::map<std::string, nlohmann::json> case_beds(Database& db, long long study_id) {
  // Only the chosen result of each case is parsed (instr() picks the
  // candidates without parsing any).
  auto st = db.prepare(
      "SELECT c.case_name, CASE WHEN json_valid(r.result_json) THEN json_extract(r.result_json, '$.bed') END FROM "
      " (SELECT s.case_name AS case_name, MIN(r.job_id) AS job_id FROM series s "
      "   JOIN study_jobs sj ON sj.series_id = s.id JOIN results r ON r.job_id = sj.job_id "
      "  WHERE s.study_id = ? AND instr(r.result_json, '\"bed\"') > 0 GROUP BY s.case_name) c "
      "JOIN results r ON r.job_id = c.job_id");
  st.bind_all(study_id);
  std::map<std::string, nlohmann::json> out;
  while (st.step()) {
    if (st.is_null(1)) continue;
    auto bed = nlohmann::json::parse(st.as_text(1), nullptr, false);
    if (bed.is_object()) out[st.as_text(0)] = std::move(bed);
  }
  return out;
}

}  // namespace gridfree
