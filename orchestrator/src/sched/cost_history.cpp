// read_cost_history (sched/cost_history.h).
#include "sched/cost_history.h"

#include "store/sqlite.h"

namespace gridfree {

CostHistory read_cost_history(const std::filesystem::path& db_file) {
  CostHistory history;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(db_file, ec)) return history;
  Database db(db_file, false);
  auto st = db.prepare(
      "SELECT j.spec_json, r.nx, r.ny, r.nz, r.cpu_s FROM jobs j JOIN results r ON r.job_id = j.id "
      "WHERE r.status = 'converged' AND r.cpu_s > 0 AND r.nx > 0 AND r.ny > 0 AND r.nz > 0");
  while (st.step()) {
    const auto spec = nlohmann::json::parse(st.as_text(0), nullptr, false);
    if (!spec.is_object()) continue;
    const double cells = static_cast<double>(st.as_int(1)) * static_cast<double>(st.as_int(2)) *
                         static_cast<double>(st.as_int(3));
    history[cost_similarity_key(spec)].push_back({cells, st.as_double(4)});
  }
  return history;
}

}  // namespace gridfree
