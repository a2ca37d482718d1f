// SPDX-License-Identifier: GPL-3.0-or-later
// Cost estimates and the plan of external studies (study/external_plan.h).
#include "study/external_plan.h"

#include <cmath>
#include <set>

#include "study/format_number.h"

namespace gridfree {

namespace {

// The means of x and y and the sums of squares about them of points (x, y).
struct LineSums {
  double mx = 0, my = 0, sxx = 0, sxy = 0;
};

LineSums line_sums(const std::vector<std::pair<double, double>>& xy) {
  LineSums s;
  for (const auto& [x, y] : xy) {
    s.mx += x;
    s.my += y;
  }
  s.mx /= static_cast<double>(xy.size());
  s.my /= static_cast<double>(xy.size());
  for (const auto& [x, y] : xy) {
    s.sxx += (x - s.mx) * (x - s.mx);
    s.sxy += (x - s.mx) * (y - s.my);
  }
  return s;
}

}  // namespace

double fit_cpu_seconds(const std::vector<CostSample>& samples, double cells, double* exponent) {
  std::vector<std::pair<double, double>> xy;  // ln cells, ln cpu
  for (const auto& s : samples)
    if (s.cells > 0 && s.cpu_s > 0 && std::isfinite(s.cpu_s)) xy.emplace_back(std::log(s.cells), std::log(s.cpu_s));
  if (xy.empty() || !(cells > 0)) return NAN;
  const auto [mx, my, sxx, sxy] = line_sums(xy);
  // One measured size (sxx = 0): CPU time proportional to cells.
  const double b = sxx > 1e-12 ? sxy / sxx : 1.0;
  if (exponent != nullptr) *exponent = b;
  return std::exp(my + b * (std::log(cells) - mx));
}

double fit_memory_mb(const std::vector<CostSample>& samples, double cells) {
  std::vector<std::pair<double, double>> xy;  // cells, MiB
  for (const auto& s : samples)
    if (s.cells > 0 && s.peak_rss_mb > 0 && std::isfinite(s.peak_rss_mb)) xy.emplace_back(s.cells, s.peak_rss_mb);
  if (xy.empty() || !(cells > 0)) return NAN;
  const auto [mx, my, sxx, sxy] = line_sums(xy);
  double fit = 0;
  if (sxx <= 1e-12 * mx * mx) {
    fit = my * std::max(1.0, cells / mx);  // one size: its peak, proportional to cells above it
  } else {
    double b = sxy / sxx, a = my - b * mx;
    if (b < 0) {  // memory falling with cells: noise; the largest peak
      b = 0;
      a = 0;
      for (const auto& [x, y] : xy) a = std::max(a, y);
    } else if (a < 0) {  // through the origin
      double sxy0 = 0, sxx0 = 0;
      for (const auto& [x, y] : xy) {
        sxy0 += x * y;
        sxx0 += x * x;
      }
      a = 0;
      b = sxy0 / sxx0;
    }
    fit = a + b * cells;
  }
  for (const auto& [x, y] : xy)
    if (x <= cells) fit = std::max(fit, y);  // never below a measured peak at as many cells or fewer
  return fit;
}

ExternalJobCost external_job_estimate(std::optional<double> cpu_s_per_cell, std::optional<double> mb_per_cell,
                                      const std::vector<CostSample>* samples, double cells) {
  ExternalJobCost out;
  const std::size_t measured = samples == nullptr ? 0 : samples->size();
  if (mb_per_cell) {
    out.memory_bytes = *mb_per_cell * cells * 1024 * 1024;
    out.memory_basis = "declared " + format_number("%.3g", *mb_per_cell) + " MB per cell";
  } else if (const double mb = measured > 0 ? fit_memory_mb(*samples, cells) : NAN; std::isfinite(mb)) {
    out.memory_bytes = kExternalMemorySafety * mb * 1024 * 1024;
    double largest = 0, at = 0;
    for (const auto& s : *samples)
      if (s.peak_rss_mb > largest) {
        largest = s.peak_rss_mb;
        at = s.cells;
      }
    out.memory_basis = "history: peak memory of " + std::to_string(measured) + " finished job(s) of the case (largest " +
                       format_number("%.0f", largest) + " MiB at " + format_number("%.0f", at) +
                       " cells), a + b·cells x " + format_number("%g", kExternalMemorySafety);
  } else {
    out.memory_basis = "unknown (no cost.mb_per_cell and no finished job of the case yet)";
  }
  if (cpu_s_per_cell) {
    out.cpu_s = *cpu_s_per_cell * cells;
    out.basis = "declared " + format_number("%.3g", *cpu_s_per_cell) + " CPU s per cell";
    return out;
  }
  if (measured > 0) {
    double b = 1;
    out.cpu_s = fit_cpu_seconds(*samples, cells, &b);
    if (std::isfinite(out.cpu_s)) {
      out.basis = "history: " + std::to_string(measured) + " finished job(s) of the case, CPU s ∝ cells^" +
                  format_number("%.2f", b);
      return out;
    }
  }
  out.basis = "unknown (no cost.cpu_s_per_cell and no finished job of the case yet)";
  return out;
}

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
    row.memory_basis = cost.memory_basis;
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
