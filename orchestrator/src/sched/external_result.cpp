// SPDX-License-Identifier: GPL-3.0-or-later
// Results of external jobs (sched/external_result.h).
#include "sched/external_result.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "sched/job_timeout.h"

namespace gridfree {

void note_collect_spec(const nlohmann::json& spec, ResultRow& row) {
  if (row.result_json.empty() || !spec.is_object()) return;
  const auto c = spec.find("case");
  if (c == spec.end() || !c->is_object() || !c->contains("external")) return;
  const nlohmann::json& ext = (*c)["external"];
  if (!ext.is_object() || !ext.contains("collect")) return;
  auto doc = nlohmann::json::parse(row.result_json, nullptr, false);
  if (!doc.is_object()) return;
  doc["collected_with"] = ext["collect"];
  row.result_json = doc.dump();
}

bool is_external_job(const nlohmann::json& spec) {
  return spec.is_object() && spec.contains("case") && spec["case"].is_object() && spec["case"].contains("external");
}

void note_external_result(const ClaimedJob& job, ResultRow& row) {
  if (!is_external_job(job.spec)) return;
  note_collect_spec(job.spec, row);
  if (row.cells == std::array<int, 3>{}) row.cells = job.cells;
}

std::map<std::string, DeclaredCost> declared_external_costs(const nlohmann::json& definition) {
  std::map<std::string, DeclaredCost> out;
  if (!definition.is_object() || !definition.contains("cases") || !definition["cases"].is_object()) return out;
  for (const auto& [name, c] : definition["cases"].items()) {
    if (!c.is_object() || !c.contains("external")) continue;
    DeclaredCost& d = out[name];
    const auto cpu = nlohmann::json::json_pointer("/external/cost/cpu_s_per_cell");
    const auto mb = nlohmann::json::json_pointer("/external/cost/mb_per_cell");
    if (c.contains(cpu) && c.at(cpu).is_number()) d.cpu_s_per_cell = c.at(cpu).get<double>();
    if (c.contains(mb) && c.at(mb).is_number()) d.mb_per_cell = c.at(mb).get<double>();
  }
  return out;
}

ExternalJobCost external_claimed_cost(const ClaimedJob& job, const std::map<std::string, DeclaredCost>& declared,
                                      const CostHistory& history) {
  const std::string name = job.spec["case"].value("name", "");
  const auto d = declared.find(name);
  const auto h = history.find(cost_similarity_key(job.spec));
  const double cells = static_cast<double>(job.cells[0]) * job.cells[1] * job.cells[2];
  return external_job_estimate(d == declared.end() ? std::nullopt : d->second.cpu_s_per_cell,
                               d == declared.end() ? std::nullopt : d->second.mb_per_cell,
                               h == history.end() ? nullptr : &h->second, cells);
}

double external_job_timeout_s(const ExternalJobCost& cost) {
  if (!std::isfinite(cost.cpu_s)) return 0;  // unknown cost: no default timeout
  return std::max(kMinJobTimeoutS, kJobTimeoutMargin * cost.cpu_s);
}

std::string converged_message(const ResultRow& row) {
  char buf[96];
  std::string values;
  if (row.dp_star) {
    std::snprintf(buf, sizeof buf, "dp* = %.6g", *row.dp_star);
    values = buf;
  } else {
    const auto doc = nlohmann::json::parse(row.result_json, nullptr, false);
    if (doc.is_object() && doc.contains("quantities") && doc["quantities"].is_object())
      for (const auto& [name, v] : doc["quantities"].items()) {
        if (!v.is_number()) continue;
        std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
        values += (values.empty() ? "" : ", ") + name + " = " + buf;
      }
  }
  std::snprintf(buf, sizeof buf, " (%.1f s)", row.wall_s);
  return "converged " + values + buf;
}

}  // namespace gridfree
