// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates and the plan of external studies (study/external_plan.h).
#include "study/external_plan.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace gridfree {

ExternalJobCost external_job_cost(const ExternalCase& c, const nlohmann::json& job_doc, double cells,
                                  const CostHistory& history) {
  const auto it = history.find(cost_similarity_key(job_doc));
  return external_job_estimate(c.cpu_s_per_cell, c.mb_per_cell, it == history.end() ? nullptr : &it->second, cells);
}

Plan make_external_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
                        const CostHistory& history) {
  Plan plan;
  plan.external = true;
  plan.workers = std::max(1, workers);
  plan.threads_per_worker = std::max(1, cores / plan.workers);
  plan.rows.resize(expanded.series.size());
  for (std::size_t s = 0; s < expanded.series.size(); ++s) {
    plan.rows[s].series = expanded.series[s].label();
    plan.rows[s].cost_basis = "unknown";
  }
  std::map<std::string, std::size_t> counted;  // job hash → the series whose row counts it
  for (const auto& job : expanded.jobs) {
    const auto [at, fresh] = counted.emplace(job.hash, job.series);
    if (!fresh) {  // the case's other quantities read this job: counted once, where it was first
      if (plan.rows[job.series].grids == 0) plan.rows[job.series].reads_jobs_of = plan.rows[at->second].series;
      continue;
    }
    const StudyCase* c = study.find_case(expanded.series[job.series].case_name);
    if (c == nullptr || !c->external) continue;
    PlanRow& row = plan.rows[job.series];
    const double cells = job.doc["numerics"]["grid"].value("cells", 0.0);
    const ExternalJobCost cost = external_job_cost(*c->external, job.doc, cells, history);
    const bool first = row.grids == 0;
    row.grids += 1;
    row.cells += static_cast<std::uint64_t>(cells);
    row.largest_cells = std::max<std::uint64_t>(row.largest_cells, static_cast<std::uint64_t>(cells));
    // Memory: the largest grid's, unknown once one grid's is (its sentence kept).
    if (first || (!std::isnan(row.memory_bytes) && (std::isnan(cost.memory_bytes) || cost.memory_bytes >= row.memory_bytes))) {
      row.memory_bytes = cost.memory_bytes;
      row.memory_basis = cost.memory_basis;
    }
    // CPU: the sum, unknown once one grid's is.
    if (first || !std::isnan(row.seconds)) {
      row.seconds = first ? cost.cpu_s : row.seconds + cost.cpu_s;  // NaN stays NaN: unknown
      row.cost_basis = cost.basis;
    }
    row.cost_source = row.cost_basis.rfind("history", 0) == 0 ? CostSource::kHistory : CostSource::kAPriori;
    row.cost_ratio_min = row.cost_ratio_max = 1;
  }
  plan.jobs = counted.size();
  for (const auto& row : plan.rows) {
    plan.cells += row.cells;
    if (row.grids == 0) continue;
    plan.max_memory_bytes = std::isnan(row.memory_bytes) || std::isnan(plan.max_memory_bytes)
                                ? NAN
                                : std::max(plan.max_memory_bytes, row.memory_bytes);
    plan.seconds += row.seconds;
  }
  plan.wall_seconds = plan.seconds / plan.workers;
  return plan;
}

}  // namespace gridfree
