// SPDX-License-Identifier: GPL-3.0-or-later
// plan --target-rde of an external study (sched/external_target.h).
#include "sched/external_target.h"

#include <algorithm>
#include <cstdio>

#include "store/sqlite.h"
#include "study/external_plan.h"
#include "study/format_number.h"

namespace gridfree {
namespace {

std::string percent_text(double fraction) { return format_number("%.3g", 100 * fraction) + " %"; }

// (h, RDE) of every grid of the finished series of the same case and quantity.
RdeModel fitted_model(const std::filesystem::path& db_file, const std::string& case_key, const std::string& quantity) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(db_file, ec)) return {};
  Database db(db_file, false);
  std::vector<std::array<double, 2>> points;
  std::size_t similar = 0;
  auto series = db.prepare(
      "SELECT se.id, (SELECT j.spec_json FROM study_jobs sj JOIN jobs j ON j.id = sj.job_id "
      "WHERE sj.series_id = se.id LIMIT 1) FROM series se WHERE se.quantity = ? "
      "AND EXISTS (SELECT 1 FROM uncertainties u WHERE u.series_id = se.id)");
  series.bind_all(quantity);
  while (series.step()) {
    const auto spec = nlohmann::json::parse(series.as_text(1), nullptr, false);
    if (!spec.is_object() || cost_similarity_key(spec) != case_key) continue;
    ++similar;
    auto u = db.prepare("SELECT delta_star, rde FROM uncertainties WHERE series_id = ? AND rde IS NOT NULL");
    u.bind_all(series.as_int(0));
    while (u.step()) points.push_back({u.as_double(0), u.as_double(1)});
  }
  RdeModel m = fit_rde_model(points);
  m.similar_series = similar;
  return m;
}

std::string model_text(const RdeModel& m) {
  if (m.a_priori)
    return "RDE unknown: no finished series of this case and quantity in the database (gridfree's a-priori RDE "
           "model describes its own solver); run the study's grids, or its first grids, and plan again with --db";
  return "RDE(h) = " + format_number("%.3g", m.a) + " · h^" + format_number("%.3g", m.p) + " (a fraction) — fitted to " +
         std::to_string(m.points) + " (h, RDE) of " + std::to_string(m.similar_series) + " finished series";
}

std::string number_or_unknown(double x, const char* format) {
  return std::isnan(x) ? std::string("unknown") : format_number(format, x);
}

}  // namespace

ExternalTargetPlan plan_external_target(const Study& study, const ExpandedStudy& expanded, double target,
                                        const std::filesystem::path& db_file, const CostHistory& history) {
  ExternalTargetPlan plan;
  plan.target_rde = target;
  for (const auto& key : expanded.series) {
    const StudyCase* c = study.find_case(key.case_name);
    if (c == nullptr || !c->external) continue;
    ExternalTargetSeries s;
    s.label = key.label();
    const GridVariables& grids = external_grids_of(study, c->name);
    std::string case_key;
    for (std::size_t k = 0; k < external_grid_count(grids); ++k) {
      const ExternalGrid g = external_grid(*c->external, grids, k);
      const auto doc = external_job_document(*c->external, c->name, g, k, key.levels);
      if (k == 0) case_key = cost_similarity_key(doc);
      ExternalTargetGrid t;
      t.h = g.h;
      for (const auto& [name, values] : grids) t.variables[name] = values[k];
      if (g.cells) t.cells = std::max(1.0, std::round(*g.cells));
      const ExternalJobCost cost = external_job_cost(*c->external, doc, std::isnan(t.cells) ? 1.0 : t.cells, history);
      t.cpu_s = cost.cpu_s;
      t.cost_basis = cost.basis;
      s.grids.push_back(std::move(t));
    }
    std::sort(s.grids.begin(), s.grids.end(), [](const auto& a, const auto& b) { return a.h > b.h; });
    s.model = fitted_model(db_file, case_key, key.quantity);
    std::size_t first_met = s.grids.size();
    if (!s.model.a_priori)
      for (std::size_t k = 0; k < s.grids.size(); ++k) {
        s.grids[k].predicted_rde = s.model.predict(s.grids[k].h);
        if (first_met == s.grids.size() && s.grids[k].predicted_rde <= target) first_met = k;
      }
    const bool enough = s.grids.size() >= kMinGridsForConverged;
    s.reachable = first_met < s.grids.size() && enough;
    const std::size_t last = s.reachable ? std::max(first_met, kMinGridsForConverged - 1) : s.grids.size() - 1;
    for (std::size_t k = 0; k < s.grids.size() && k <= last; ++k) {
      s.grids[k].needed = !s.model.a_priori;  // unknown without an RDE model
      s.grids_needed += 1;
      s.cpu_s += s.grids[k].cpu_s;
    }
    plan.series.push_back(std::move(s));
  }
  return plan;
}

std::string external_target_text(const ExternalTargetPlan& p) {
  std::string out = "target RDE " + percent_text(p.target_rde) + " (external code: RDE(h) fitted per series to the " +
                    "finished series of the same case and quantity in --db; costs by the external estimate)\n";
  char line[256];
  for (const auto& s : p.series) {
    out += "\nseries " + s.label + ": " + model_text(s.model) + "\n";
    std::string header = "  h            ";
    if (!s.grids.empty())
      for (const auto& [name, v] : s.grids.front().variables) header += name + std::string(std::max<std::size_t>(1, 10 - name.size()), ' ');
    std::snprintf(line, sizeof line, "%s%10s %14s %10s  %s\n", header.c_str(), "cells", "predicted RDE", "CPU s", "needed");
    out += line;
    for (const auto& g : s.grids) {
      std::string row = "  " + format_number("%-12.4g", g.h) + " ";
      for (const auto& [name, v] : g.variables) {
        const std::string text = format_number("%.6g", v);
        row += text + std::string(std::max<std::size_t>(1, std::max<std::size_t>(10, name.size() + 1) - text.size()), ' ');
      }
      std::snprintf(line, sizeof line, "%s%10s %14s %10s  %s\n", row.c_str(), number_or_unknown(g.cells, "%.0f").c_str(),
                    std::isnan(g.predicted_rde) ? "unknown" : percent_text(g.predicted_rde).c_str(),
                    number_or_unknown(g.cpu_s, "%.3g").c_str(), g.needed ? "yes" : "");
      out += line;
    }
    const std::string basis = s.grids.empty() ? std::string() : s.grids.front().cost_basis;
    const std::string cost = std::isnan(s.cpu_s) ? "cost " + basis : format_number("%.3g", s.cpu_s) + " CPU s (" + basis + ")";
    if (s.model.a_priori)
      out += "  which grid reaches the target: unknown (no RDE model yet); all " + std::to_string(s.grids.size()) +
             " grids: " + cost + "\n";
    else if (s.reachable)
      out += "  needs " + std::to_string(s.grids_needed) + " grids (h " + format_number("%.4g", s.grids.front().h) +
             " → " + format_number("%.4g", s.grids[s.grids_needed - 1].h) + "): " + cost + "\n";
    else
      out += "  target not reachable on these grids: the finest predicts RDE " +
             percent_text(s.grids.empty() ? 0.0 : s.grids.back().predicted_rde) +
             (s.grids.size() < kMinGridsForConverged ? " and a converged verdict needs " +
                                                           std::to_string(kMinGridsForConverged) + " grids"
                                                     : std::string()) +
             "; all " + std::to_string(s.grids_needed) + " grids: " + cost + "\n";
  }
  return out;
}

nlohmann::json external_target_json(const ExternalTargetPlan& p) {
  auto number = [](double x) { return std::isnan(x) ? nlohmann::json() : nlohmann::json(x); };
  nlohmann::json series = nlohmann::json::array();
  for (const auto& s : p.series) {
    nlohmann::json grids = nlohmann::json::array();
    for (const auto& g : s.grids)
      grids.push_back({{"h", g.h},
                       {"variables", g.variables},
                       {"cells", number(g.cells)},
                       {"predicted_rde", number(g.predicted_rde)},
                       {"cpu_s", number(g.cpu_s)},
                       {"cost_basis", g.cost_basis},
                       {"needed", g.needed}});
    nlohmann::json model = nullptr;
    if (!s.model.a_priori)
      model = {{"form", "RDE = a * h^p"}, {"a", s.model.a}, {"p", s.model.p}, {"points", s.model.points},
               {"similar_series", s.model.similar_series}};
    series.push_back({{"series", s.label},
                      {"model", model},
                      {"basis", model_text(s.model)},
                      {"reachable", s.reachable},
                      {"grids_needed", s.grids_needed},
                      {"cpu_s", number(s.cpu_s)},
                      {"grids", grids}});
  }
  return {{"target_rde", p.target_rde}, {"series", series}};
}

}  // namespace gridfree
