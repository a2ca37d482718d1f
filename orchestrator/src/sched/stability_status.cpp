// SPDX-License-Identifier: GPL-3.0-or-later
// The stability part of `status --json` (stability_status.h).
#include "sched/stability_status.h"

namespace gridfree {

nlohmann::json stability_status(Store& store, long long study_id) {
  nlohmann::json counts = nlohmann::json::object(), series = nlohmann::json::array();
  auto st = store.db().prepare(
      "SELECT v.series_id, v.case_name, v.convection, v.fwhm_dp, v.drag, v.deposition, v.delta_star, "
      "v.delta_star_nominal, v.outcome, COALESCE(v.iterations, 0), COALESCE(v.reason, '') "
      "FROM v_stability v JOIN series se ON se.id = v.series_id WHERE se.study_id = ? "
      "ORDER BY se.position, v.series_id, v.delta_star DESC");
  st.bind_all(study_id);
  long long current = -1;
  while (st.step()) {
    const long long id = st.as_int(0);
    if (id != current) {
      current = id;
      series.push_back({{"series_id", id},
                        {"case", st.as_text(1)},
                        {"convection", st.as_text(2)},
                        {"fwhm_dp", st.as_double(3)},
                        {"drag", st.as_text(4)},
                        {"deposition", st.as_text(5)},
                        {"grids", nlohmann::json::array()}});
    }
    const std::string outcome = st.as_text(8);
    nlohmann::json g = {{"delta_star", st.as_double(6)},
                        {"delta_star_nominal", st.is_null(7) ? nlohmann::json(nullptr) : nlohmann::json(st.as_double(7))},
                        {"outcome", outcome},
                        {"iterations", st.as_int(9)}};
    if (outcome != "converged") g["reason"] = st.as_text(10);
    series.back()["grids"].push_back(std::move(g));
    counts[outcome] = counts.value(outcome, 0) + 1;
  }
  return {{"counts", counts}, {"series", series}};
}

}  // namespace gridfree
