// Results of external jobs (sched/external_result.h).
#include "sched/external_result.h"

#include <algorithm>
#include <array>
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

std::map<std::string, double> declared_cpu_s_per_cell(const nlohmann::json& definition) {
  std::map<std::string, double> out;
  if (!definition.is_object() || !definition.contains("cases") || !definition["cases"].is_object()) return out;
  for (const auto& [name, c] : definition["cases"].items()) {
    const auto p = nlohmann::json::json_pointer("/external/cost/cpu_s_per_cell");
    if (c.is_object() && c.contains(p) && c.at(p).is_number()) out[name] = c.at(p).get<double>();
  }
  return out;
}

double external_job_timeout_s(const ClaimedJob& job, const std::map<std::string, double>& cpu_s_per_cell) {
  const std::string name = job.spec["case"].value("name", "");
  const auto it = cpu_s_per_cell.find(name);
  if (it == cpu_s_per_cell.end()) return 0;  // unknown cost: no default timeout
  const double cells = static_cast<double>(job.cells[0]) * job.cells[1] * job.cells[2];
  return std::max(kMinJobTimeoutS, kJobTimeoutMargin * it->second * cells);
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
