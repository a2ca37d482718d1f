// SPDX-License-Identifier: GPL-3.0-or-later
// prior_rde_model (sched/adaptive_prior.h).
#include "sched/adaptive_prior.h"

#include <set>
#include <tuple>

#include "store/sqlite.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

nlohmann::json without_name(nlohmann::json c) {
  if (c.is_object()) c.erase("name");
  return c;
}

}  // namespace

RdeModel prior_rde_model(const std::filesystem::path& db_file, const Study& study) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(db_file, ec)) return {};
  Database db(db_file, false);
  std::vector<nlohmann::json> cases;
  for (const auto& c : study.cases) cases.push_back(without_name(c.doc));
  std::set<std::tuple<std::string, double, std::string, std::string>> levels;
  for (const auto& k : design_series(study)) levels.insert({k.convection, k.fwhm_dp, k.drag, k.deposition});

  std::vector<std::array<double, 2>> points;
  double measured = 0, model = 0;
  std::size_t similar = 0;
  auto series = db.prepare(
      "SELECT se.id, se.convection, se.fwhm_dp, se.drag, se.deposition, "
      " (SELECT j.spec_json FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id WHERE sj.series_id = se.id LIMIT 1) "
      "FROM series se WHERE EXISTS (SELECT 1 FROM uncertainties u WHERE u.series_id = se.id)");
  while (series.step()) {
    if (!levels.count({series.as_text(1), series.as_double(2), series.as_text(3), series.as_text(4)})) continue;
    const auto spec = nlohmann::json::parse(series.as_text(5), nullptr, false);
    if (!spec.is_object() || !spec.contains("case")) continue;
    const auto c = without_name(spec["case"]);
    if (std::find(cases.begin(), cases.end(), c) == cases.end()) continue;
    ++similar;
    auto u = db.prepare("SELECT delta_star, rde FROM uncertainties WHERE series_id = ? AND rde IS NOT NULL");
    u.bind_all(series.as_int(0));
    while (u.step()) points.push_back({u.as_double(0), u.as_double(1)});
    auto t = db.prepare(
        "SELECT r.cpu_s, j.nx, j.ny, j.nz FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
        "JOIN results r ON r.job_id = j.id WHERE sj.series_id = ? AND r.cpu_s > 0");
    t.bind_all(series.as_int(0));
    while (t.step()) {
      measured += t.as_double(0);
      const std::array<int, 3> cells = {static_cast<int>(t.as_int(1)), static_cast<int>(t.as_int(2)),
                                        static_cast<int>(t.as_int(3))};
      model += estimated_seconds(cells, 1, apriori_cost_ratio(spec, cells).ratio);
    }
  }
  RdeModel m = fit_rde_model(points);
  m.similar_series = similar;
  if (!m.a_priori && measured > 0 && model > 0) m.cost_scale = measured / model;
  return m;
}

}  // namespace gridfree
