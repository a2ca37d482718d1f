// Cost estimates and the plan of external studies (study/external_plan.h).
#include "study/external_plan.h"

#include <cmath>
#include <set>

#include "study/format_number.h"

namespace gridfree {

double fit_cpu_seconds(const std::vector<CostSample>& samples, double cells, double* exponent) {
  std::vector<std::pair<double, double>> xy;  // ln cells, ln cpu
  for (const auto& s : samples)
    if (s.cells > 0 && s.cpu_s > 0 && std::isfinite(s.cpu_s)) xy.emplace_back(std::log(s.cells), std::log(s.cpu_s));
  if (xy.empty() || !(cells > 0)) return NAN;
  double mx = 0, my = 0;
  for (const auto& [x, y] : xy) {
    mx += x;
    my += y;
  }
  mx /= static_cast<double>(xy.size());
  my /= static_cast<double>(xy.size());
  double sxx = 0, sxy = 0;
  for (const auto& [x, y] : xy) {
    sxx += (x - mx) * (x - mx);
    sxy += (x - mx) * (y - my);
  }
  // One measured size (sxx = 0): CPU time proportional to cells.
  const double b = sxx > 1e-12 ? sxy / sxx : 1.0;
  if (exponent != nullptr) *exponent = b;
  return std::exp(my + b * (std::log(cells) - mx));
}

ExternalJobCost external_job_cost(const ExternalCase& c, const nlohmann::json& job_doc, double cells,
                                  const CostHistory& history) {
  ExternalJobCost out;
  if (c.mb_per_cell) out.memory_bytes = *c.mb_per_cell * cells * 1024 * 1024;
  if (c.cpu_s_per_cell) {
    out.cpu_s = *c.cpu_s_per_cell * cells;
    out.basis = "declared " + format_number("%.3g", *c.cpu_s_per_cell) + " CPU s per cell";
    return out;
  }
  const auto it = history.find(cost_similarity_key(job_doc));
  if (it != history.end() && !it->second.empty()) {
    double b = 1;
    out.cpu_s = fit_cpu_seconds(it->second, cells, &b);
    if (std::isfinite(out.cpu_s)) {
      out.basis = "history: " + std::to_string(it->second.size()) + " finished job(s) of the case, CPU s ∝ cells^" +
                  format_number("%.2f", b);
      return out;
    }
  }
  out.basis = "unknown (no cost.cpu_s_per_cell and no finished job of the case yet)";
  return out;
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
  std::set<std::string> counted;
  for (const auto& job : expanded.jobs) {
    if (!counted.insert(job.hash).second) continue;  // the case's other quantities read this job
    const StudyCase* c = study.find_case(expanded.series[job.series].case_name);
    if (c == nullptr || !c->external) continue;
    PlanRow& row = plan.rows[job.series];
    const double cells = job.doc["numerics"]["grid"].value("cells", 0.0);
    const ExternalJobCost cost = external_job_cost(*c->external, job.doc, cells, history);
    row.grids += 1;
    row.cells += static_cast<std::uint64_t>(cells);
    row.largest_cells = std::max<std::uint64_t>(row.largest_cells, static_cast<std::uint64_t>(cells));
    row.memory_bytes = row.grids == 1 ? cost.memory_bytes : std::max(row.memory_bytes, cost.memory_bytes);
    row.seconds = row.grids == 1 ? cost.cpu_s : row.seconds + cost.cpu_s;  // NaN stays NaN: unknown
    row.cost_basis = cost.basis;
    row.cost_source = cost.basis.rfind("history", 0) == 0 ? CostSource::kHistory : CostSource::kAPriori;
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
