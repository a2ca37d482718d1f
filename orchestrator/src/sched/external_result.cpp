// SPDX-License-Identifier: GPL-3.0-or-later
// Results of external jobs (sched/external_result.h).
#include "sched/external_result.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "sched/job_timeout.h"
#include "study/external_intake.h"

namespace gridfree {

void note_collect_spec(const nlohmann::json& spec, ResultRow& row) { record_collect_spec(spec, row.result_json); }

bool is_external_job(const nlohmann::json& spec) {
  return spec.is_object() && spec.contains("case") && spec["case"].is_object() && spec["case"].contains("external");
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
