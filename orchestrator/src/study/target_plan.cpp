// SPDX-License-Identifier: GPL-3.0-or-later
// plan --target-rde (study/target_plan.h).
#include "study/target_plan.h"

#include "study/format_number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "grid/grid.h"
#include "study/study_plan.h"

namespace gridfree {
namespace {

std::string pct(double fraction) { return format_number("%.3g", 100 * fraction) + " %"; }

std::string too_few_grids_text(const TargetCasePlan& c) {
  return "the study gives case " + c.case_name + " " + std::to_string(c.grids.size()) +
         " grids and a converged verdict needs " + std::to_string(kMinGridsForConverged) +
         " (n - 3 >= 2 degrees of freedom): add " + std::to_string(kMinGridsForConverged - c.grids.size()) +
         " more grid(s)";
}

}  // namespace

double RdeModel::predict(double delta_star) const { return a * std::pow(delta_star, p); }

RdeModel fit_rde_model(const std::vector<std::array<double, 2>>& pts) {
  RdeModel m;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  double xmin = INFINITY, xmax = -INFINITY;
  for (const auto& [h, rde] : pts) {
    if (!(h > 0) || !(rde > 0) || !std::isfinite(h) || !std::isfinite(rde)) continue;
    const double x = std::log(h), y = std::log(rde);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    n += 1;
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
  }
  if (n < 2 || xmax - xmin < 1e-9) return m;
  const double det = n * sxx - sx * sx;
  m.p = (n * sxy - sx * sy) / det;
  m.a = std::exp((sy - m.p * sx) / n);
  m.a_priori = false;
  m.points = static_cast<std::size_t>(n);
  return m;
}

std::vector<std::pair<double, std::array<int, 3>>> candidate_grids(const Study& s, const StudyCase& c) {
  std::vector<std::pair<double, std::array<int, 3>>> out;
  for (const auto& cells : grids_for_case(s, c)) out.emplace_back(delta_star_of(c.spec.domain_dp, cells), cells);
  if (!s.grid_delta_star.empty())  // the nominal Δ* where the study gives them
    for (std::size_t k = 0; k < out.size(); ++k) out[k].first = s.grid_delta_star[k];
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  return out;
}

TargetPlan plan_for_target(const Study& s, double target, const RdeModel& model, const CostHistory& history) {
  TargetPlan plan;
  plan.target_rde = target;
  plan.model = model;
  const auto series = design_series(s);
  for (const auto& c : s.cases) {
    TargetCasePlan cp;
    cp.case_name = c.name;
    cp.series = static_cast<std::size_t>(
        std::count_if(series.begin(), series.end(), [&](const SeriesKey& k) { return k.case_name == c.name; }));
    const auto ds = candidate_grids(s, c);
    const auto first = std::find_if(series.begin(), series.end(), [&](const SeriesKey& k) { return k.case_name == c.name; });
    std::size_t first_met = ds.size();
    for (std::size_t k = 0; k < ds.size(); ++k) {
      TargetGrid g;
      g.delta_star = ds[k].first;
      g.cells = ds[k].second;
      g.predicted_rde = model.predict(g.delta_star);
      const auto doc = first != series.end() ? make_job_document(s, *first, g.cells) : nlohmann::json{{"case", c.doc}};
      const CostRatio r = job_cost_ratio(history, doc, g.cells);
      const bool measured = r.source == CostSource::kHistory;
      g.cpu_s = (measured ? r.ratio : model.cost_scale * r.ratio) * estimated_seconds(g.cells, 1);
      g.cost_from_history = measured;
      cp.costs_from_history = cp.costs_from_history || measured;
      g.memory_bytes = estimated_memory_bytes(g.cells);
      if (first_met == ds.size() && g.predicted_rde <= target) first_met = k;
      cp.grids.push_back(g);
    }
    cp.enough_grids = ds.size() >= kMinGridsForConverged;
    cp.reachable = first_met < ds.size() && cp.enough_grids;
    const std::size_t last = cp.reachable ? std::max(first_met, kMinGridsForConverged - 1) : ds.size() - 1;
    for (std::size_t k = 0; k < cp.grids.size() && k <= last; ++k) {
      cp.grids[k].needed = true;
      cp.grids_needed += 1;
      cp.cpu_s_per_series += cp.grids[k].cpu_s;
      cp.peak_memory_bytes = std::max(cp.peak_memory_bytes, cp.grids[k].memory_bytes);
    }
    plan.total_cpu_s += cp.cpu_s_per_series * static_cast<double>(cp.series);
    plan.peak_memory_bytes = std::max(plan.peak_memory_bytes, cp.peak_memory_bytes);
    plan.cases.push_back(std::move(cp));
  }
  return plan;
}

std::string rde_model_text(const RdeModel& m) {
  std::string out = "RDE(Δ*) = " + pct(m.a) + " · Δ*^" + format_number("%.3g", m.p);
  if (m.a_priori)
    return out + " — a-priori: no finished similar series in the database; p = 1 and the coefficient "
                 "assumed from the bursting-bubble baseline (RDE 0.78 % at Δ* 0.564, docs/BENCHMARKS.md)";
  return out + " — fitted to " + std::to_string(m.points) + " (Δ*, RDE) of " + std::to_string(m.similar_series) +
         " finished similar series";
}

std::string cost_basis_text(const TargetPlan& p) {
  std::size_t grids = 0, measured = 0;
  for (const auto& c : p.cases)
    for (const auto& g : c.grids) {
      grids += 1;
      measured += g.cost_from_history ? 1 : 0;
    }
  const std::string model =
      p.model.cost_scale == 1
          ? std::string("the a-priori cost model (study/cost_model.h)")
          : "the a-priori cost model × " + format_number("%.3g", p.model.cost_scale) +
                " (the similar series' measured CPU time / the model's)";
  const std::string history = "finished similar jobs in the database (the plan's cost ratio, study/cost_model.h)";
  if (measured == 0) return "costs from " + model;
  if (measured == grids) return "costs of every grid from " + history;
  return "costs of " + std::to_string(measured) + " of " + std::to_string(grids) + " grids from " + history +
         ", the others from " + model;
}

nlohmann::json target_plan_json(const TargetPlan& p) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& c : p.cases) {
    nlohmann::json grids = nlohmann::json::array();
    for (const auto& g : c.grids)
      grids.push_back({{"delta_star", g.delta_star},
                       {"cells", {g.cells[0], g.cells[1], g.cells[2]}},
                       {"predicted_rde", g.predicted_rde},
                       {"cpu_core_hours", g.cpu_s / 3600},
                       {"cost_source", g.cost_from_history ? "history" : "a_priori"},
                       {"memory_bytes", g.memory_bytes},
                       {"needed", g.needed}});
    cases.push_back({{"case", c.case_name},
                     {"series", c.series},
                     {"reachable", c.reachable},
                     {"enough_grids", c.enough_grids},
                     {"grids_needed", c.grids_needed},
                     {"core_hours_per_series", c.cpu_s_per_series / 3600},
                     {"peak_memory_bytes", c.peak_memory_bytes},
                     {"costs_from_history", c.costs_from_history},
                     {"grids", grids}});
  }
  return {{"target_rde", p.target_rde},
          {"model",
           {{"form", "RDE = a * delta_star^p"},
            {"a", p.model.a},
            {"p", p.model.p},
            {"a_priori", p.model.a_priori},
            {"points", p.model.points},
            {"similar_series", p.model.similar_series},
            {"cost_scale", p.model.cost_scale},
            {"basis", rde_model_text(p.model)}}},
          {"cost_basis", cost_basis_text(p)},
          {"cases", cases},
          {"total_core_hours", p.total_cpu_s / 3600},
          {"peak_memory_bytes", p.peak_memory_bytes}};
}

std::string target_plan_text(const TargetPlan& p) {
  std::string out = "target RDE " + pct(p.target_rde) + ": " + rde_model_text(p.model) + "\n" + cost_basis_text(p) + "\n";
  char line[256];
  for (const auto& c : p.cases) {
    const auto measured = std::count_if(c.grids.begin(), c.grids.end(), [](const TargetGrid& g) { return g.cost_from_history; });
    out += "\ncase " + c.case_name + " (" + std::to_string(c.series) + " series)" +
           (measured > 0 ? "; costs of " + std::to_string(measured) + " of " + std::to_string(c.grids.size()) +
                               " grids from its finished similar jobs"
                         : std::string()) +
           ":\n";
    std::snprintf(line, sizeof line, "  %-8s %-16s %14s %14s %12s  %s\n", "Δ*", "cells", "predicted RDE", "core-hours",
                  "memory", "needed");
    out += line;
    for (const auto& g : c.grids) {
      const std::string cells =
          std::to_string(g.cells[0]) + "x" + std::to_string(g.cells[1]) + "x" + std::to_string(g.cells[2]);
      std::snprintf(line, sizeof line, "  %-7.4g %-16s %14s %14.3g %12s  %s\n", g.delta_star, cells.c_str(),
                    pct(g.predicted_rde).c_str(), g.cpu_s / 3600, human_bytes(g.memory_bytes).c_str(),
                    g.needed ? "yes" : "");
      out += line;
    }
    if (!c.enough_grids)
      out += "  target not reachable: " + too_few_grids_text(c) + "; all " + std::to_string(c.grids_needed) +
             " grids cost " + format_number("%.3g", c.cpu_s_per_series / 3600) + " core-hours per series\n";
    else if (c.reachable)
      out += "  needs " + std::to_string(c.grids_needed) + " grids (Δ* " + format_number("%.4g", c.grids.front().delta_star) +
             " → " + format_number("%.4g", c.grids[c.grids_needed - 1].delta_star) + "): " +
             format_number("%.3g", c.cpu_s_per_series / 3600) + " core-hours per series, peak memory " +
             human_bytes(c.peak_memory_bytes) + "\n";
    else
      out += "  target not reachable on these grids: the finest predicts RDE " +
             pct(c.grids.empty() ? 0.0 : c.grids.back().predicted_rde) + "; all " + std::to_string(c.grids_needed) +
             " grids cost " + format_number("%.3g", c.cpu_s_per_series / 3600) + " core-hours per series\n";
  }
  out += "\ntotal: " + format_number("%.3g", p.total_cpu_s / 3600) + " core-hours, peak memory " +
         human_bytes(p.peak_memory_bytes) + "\n";
  return out;
}

std::vector<std::string> target_plan_warnings(const TargetPlan& p) {
  std::vector<std::string> out;
  for (const auto& c : p.cases)
    if (!c.enough_grids) out.push_back("--target-rde: " + too_few_grids_text(c));
  return out;
}

}  // namespace gridfree
