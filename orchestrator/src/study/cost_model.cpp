// SPDX-License-Identifier: GPL-3.0-or-later
// The cost ratio of a job (study/cost_model.h).
#include "study/cost_model.h"

#include "study/format_number.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "study/study_plan.h"

namespace gridfree {
namespace {

double number_at(const nlohmann::json& doc, const char* pointer) {
  const auto p = nlohmann::json::json_pointer(pointer);
  return doc.contains(p) && doc.at(p).is_number() ? doc.at(p).get<double>() : 0.0;
}

nlohmann::json case_of(const nlohmann::json& job_doc) {
  const auto c = job_doc.is_object() ? job_doc.find("case") : job_doc.end();
  return c != job_doc.end() && c->is_object() ? *c : nlohmann::json::object();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

std::string cost_source_name(CostSource s) { return s == CostSource::kHistory ? "history" : "a-priori"; }

double particle_reynolds(const nlohmann::json& c) {
  const double rho = number_at(c, "/gas/density_g_cm3"), mu = number_at(c, "/gas/viscosity_g_cm_s");
  const double d = number_at(c, "/particle_diameter_cm");
  const double u0 = number_at(c, "/boundaries/y_low/superficial_velocity_cm_s");
  return mu > 0 ? rho * std::abs(u0) * d / mu : 0.0;
}

CostRatio apriori_cost_ratio(const nlohmann::json& job_doc, const std::array<int, 3>& cells) {
  const auto c = case_of(job_doc);
  const double re = particle_reynolds(c);
  const bool nested = static_cast<double>(cells[0]) * cells[1] * cells[2] >= kNestedMinCells;
  const double ref = nested ? kReferenceNestedRatio : kReferenceSingleGridRatio;
  const double w = re > 1 ? std::min(1.0, std::log(re) / std::log(kReferenceReP)) : 0.0;
  CostRatio r;
  r.ratio = 1 + (ref - 1) * w;
  r.basis = "a-priori: Re_p " + format_number("%.3g", re) + (nested ? ", nested-start grid" : ", single grid") + ": × " +
            format_number("%.3g", r.ratio) + " (1 at Re_p ≤ 1, the bubble; " + format_number("%g", ref) + " at Re_p ≥ " +
            format_number("%g", kReferenceReP) + ", the SSCP-like bed)";
  return r;
}

std::string cost_similarity_key(const nlohmann::json& job_doc) {
  auto c = case_of(job_doc);
  c.erase("name");
  c.erase("particles");
  // An external job: the same case (template, command, version) on any grid.
  if (c.contains("external") && c["external"].is_object())
    for (const char* key : {"variables", "template_dir", "collect"}) c["external"].erase(key);
  const auto drag = job_doc.is_object() && job_doc.contains("/numerics/drag"_json_pointer) ? job_doc.at("/numerics/drag"_json_pointer)
                                                                   : nlohmann::json("bvk");
  return nlohmann::json{{"case", c}, {"drag", drag}}.dump();
}

CostRatio history_cost_ratio(const std::vector<CostSample>& similar, double cells) {
  CostRatio r;
  r.ratio = 0;
  r.source = CostSource::kHistory;
  std::vector<CostSample> usable;
  for (const auto& s : similar)
    if (s.cells > 0 && s.cpu_s > 0 && std::isfinite(s.cpu_s)) usable.push_back(s);
  if (usable.empty() || !(cells > 0)) return r;
  auto distance = [&](const CostSample& s) { return std::abs(std::log(s.cells / cells)); };
  const double window = std::log(kHistoryCellWindow);
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& s : usable) nearest = std::min(nearest, distance(s));
  const double reach = std::max(window, nearest) * (1 + 1e-12);  // the window, or the nearest size
  std::vector<double> ratios;
  double lo = INFINITY, hi = 0;
  for (const auto& s : usable)
    if (distance(s) <= reach) {
      ratios.push_back(s.cpu_s / base_cpu_seconds(s.cells));
      lo = std::min(lo, s.cells);
      hi = std::max(hi, s.cells);
    }
  r.ratio = median(ratios);
  r.jobs = ratios.size();
  r.basis = "history: median of " + std::to_string(r.jobs) + " similar finished job(s) of " + format_number("%.0f", lo) +
            (hi > lo ? "–" + format_number("%.0f", hi) : std::string()) + " cells: × " + format_number("%.3g", r.ratio);
  return r;
}

CostRatio job_cost_ratio(const CostHistory& history, const nlohmann::json& job_doc, const std::array<int, 3>& cells) {
  const auto it = history.find(cost_similarity_key(job_doc));
  if (it != history.end()) {
    const double n = static_cast<double>(cells[0]) * cells[1] * cells[2];
    CostRatio r = history_cost_ratio(it->second, n);
    if (r.jobs > 0) return r;
  }
  return apriori_cost_ratio(job_doc, cells);
}

}  // namespace gridfree
