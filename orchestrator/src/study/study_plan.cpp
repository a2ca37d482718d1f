// SPDX-License-Identifier: GPL-3.0-or-later
// Memory and time estimates of a study's jobs (see study_plan.h for the model).
#include "study/study_plan.h"

#include "job/memory_estimate.h"
#include "study/case_kind.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace gridfree {

std::uint64_t physical_memory_bytes() { return machine_memory_bytes(); }

static double cell_count(const std::array<int, 3>& c) {
  return static_cast<double>(c[0]) * c[1] * c[2];
}

double estimated_memory_bytes(const std::array<int, 3>& cells) { return job_memory_estimate_bytes(cells); }

static double iterations_of(double n) {
  if (n >= kNestedMinCells) return kNestedIterations;
  return kBaseIterations + kIterationsPerCellRoot * std::cbrt(n);
}

double estimated_iterations(const std::array<int, 3>& cells) { return iterations_of(cell_count(cells)); }

double base_cpu_seconds(double n) { return iterations_of(n) * n * kSecondsPerCellIteration; }

double estimated_seconds(const std::array<int, 3>& cells, int threads, double cost_ratio) {
  return cost_ratio * base_cpu_seconds(cell_count(cells)) / std::max(1, threads);
}

// One job's estimate added to its series' row.
static void add_job(PlanRow& row, const std::array<int, 3>& cells, const CostRatio& r, int threads) {
  const auto n = static_cast<std::uint64_t>(cell_count(cells));
  row.cells += n;
  if (n >= row.largest_cells) row.cost_basis = r.basis;
  row.largest_cells = std::max(row.largest_cells, n);
  row.memory_bytes = std::max(row.memory_bytes, estimated_memory_bytes(cells));
  row.seconds += estimated_seconds(cells, threads, r.ratio);
  const bool first = row.cost_ratio_max == 0;
  row.cost_ratio_min = first ? r.ratio : std::min(row.cost_ratio_min, r.ratio);
  row.cost_ratio_max = std::max(row.cost_ratio_max, r.ratio);
  if (first || row.cost_source == CostSource::kHistory) row.cost_source = r.source;
}

Plan make_plan(const Study& study, const ExpandedStudy& expanded, int workers, int cores,
               const CostHistory& history) {
  return case_kind(study).plan(study, expanded, workers, cores, history);
}

Plan make_particle_bed_plan(const Study& /*study*/, const ExpandedStudy& expanded, int workers, int cores,
                            const CostHistory& history) {
  Plan plan;
  plan.workers = std::max(1, workers);
  const int threads = std::max(1, cores / plan.workers);
  plan.threads_per_worker = threads;
  plan.rows.resize(expanded.series.size());
  for (std::size_t s = 0; s < expanded.series.size(); ++s) plan.rows[s].series = expanded.series[s].label();
  for (const auto& job : expanded.jobs) {
    plan.rows[job.series].grids += 1;
    add_job(plan.rows[job.series], job.cells, job_cost_ratio(history, job.doc, job.cells), threads);
  }
  for (const auto& a : expanded.alignment) {  // alignment-check variants: solved like the grids
    plan.rows[a.series].alignment_jobs += 1;
    add_job(plan.rows[a.series], a.cells, job_cost_ratio(history, a.doc, a.cells), threads);
  }
  plan.jobs = expanded.jobs.size() + expanded.alignment.size();
  for (const auto& row : plan.rows) {
    plan.cells += row.cells;
    plan.max_memory_bytes = std::max(plan.max_memory_bytes, row.memory_bytes);
    plan.seconds += row.seconds;
  }
  plan.wall_seconds = plan.seconds / plan.workers;
  return plan;
}

// "a + b N^(1/3)" from the constants of the iteration model.
static std::string iterations_model_text() {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%g + %g N^(1/3) below %g cells, else %g (nested start)", kBaseIterations,
                kIterationsPerCellRoot, kNestedMinCells, kNestedIterations);
  return buf;
}

nlohmann::json plan_to_json(const Plan& plan) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : plan.rows) {
    rows.push_back({{"series", r.series},
                    {"grids", r.grids},
                    {"alignment_jobs", r.alignment_jobs},
                    {"cells", r.cells},
                    {"largest_cells", r.largest_cells},
                    {"memory_bytes", r.memory_bytes},
                    {"seconds", r.seconds},
                    {"cost_source", cost_source_name(r.cost_source)},
                    {"cost_ratio", {r.cost_ratio_min, r.cost_ratio_max}},
                    {"cost_basis", r.cost_basis}});
    if (!r.memory_basis.empty()) rows.back()["memory_basis"] = r.memory_basis;
    if (!r.reads_jobs_of.empty()) rows.back()["reads_jobs_of"] = r.reads_jobs_of;
  }
  return {{"series", rows},
          {"jobs", plan.jobs},
          {"cells", plan.cells},
          {"max_memory_bytes", plan.max_memory_bytes},
          {"seconds", plan.seconds},
          {"workers", plan.workers},
          {"threads_per_worker", plan.threads_per_worker},
          {"wall_seconds", plan.wall_seconds},
          {"model",
           {{"bytes_per_cell", kWorkerBytesPerCell},
            {"seconds_per_cell_iteration", kSecondsPerCellIteration},
            {"iterations", iterations_model_text()},
            {"time", "cost_ratio * iterations * cells * seconds_per_cell_iteration / threads_per_worker"}}}};
}

std::string human_bytes(double bytes) {
  if (std::isnan(bytes)) return "unknown";  // an external job without a cost figure
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024 && u < 4) {
    bytes /= 1024;
    ++u;
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %s", bytes, units[u]);
  return buf;
}

std::string human_seconds(double s) {
  if (std::isnan(s)) return "unknown";  // an external job without a cost figure
  char buf[32];
  if (s < 120)
    std::snprintf(buf, sizeof buf, "%.0f s", s);
  else if (s < 7200)
    std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
  else
    std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  return buf;
}

// "history × 1.2–2.7", "a-priori × 2".
static std::string cost_column(const PlanRow& r) {
  char buf[64];
  if (r.cost_ratio_max > r.cost_ratio_min * 1.0005)
    std::snprintf(buf, sizeof buf, "%s x %.3g-%.3g", cost_source_name(r.cost_source).c_str(), r.cost_ratio_min,
                  r.cost_ratio_max);
  else
    std::snprintf(buf, sizeof buf, "%s x %.3g", cost_source_name(r.cost_source).c_str(), r.cost_ratio_max);
  return buf;
}

std::string plan_to_table(const Plan& plan) {
  std::string out;
  char line[320];
  std::snprintf(line, sizeof line, "%-40s %5s %12s %12s %12s  %s\n", "series", "grids", "cells", "max memory",
                "est. time", "cost ratio");
  out += line;
  std::vector<std::pair<std::string, std::string>> bases;  // first series with each distinct basis
  for (const auto& r : plan.rows) {
    if (r.grids == 0 && !r.reads_jobs_of.empty()) {  // never "0 grids, 0 cells, 0.0 B, 0 s"
      out += r.series + std::string(r.series.size() < 40 ? 40 - r.series.size() : 0, ' ') + " read from the jobs of " +
             r.reads_jobs_of + " (same grids, no cost of its own)\n";
      continue;
    }
    std::snprintf(line, sizeof line, "%-40s %5zu %12llu %12s %12s  %s\n", r.series.c_str(), r.grids,
                  static_cast<unsigned long long>(r.cells), human_bytes(r.memory_bytes).c_str(),
                  human_seconds(r.seconds).c_str(), plan.external ? r.cost_basis.c_str() : cost_column(r).c_str());
    out += line;
    if (std::none_of(bases.begin(), bases.end(), [&](const auto& x) { return x.second == r.cost_basis; }))
      bases.emplace_back(r.series, r.cost_basis);
  }
  std::snprintf(line, sizeof line, "%-40s %5zu %12llu %12s %12s\n", "total (jobs)", plan.jobs,
                static_cast<unsigned long long>(plan.cells),
                human_bytes(plan.max_memory_bytes).c_str(), human_seconds(plan.seconds).c_str());
  out += line;
  if (plan.external) {
    out += "estimated wall time with " + std::to_string(plan.workers) + " workers: " +
           human_seconds(plan.wall_seconds) +
           " (external code: declared cost per cell, or measured history of the case; see the last column)\n";
    std::vector<std::string> shown;  // each distinct memory basis once, with its first series
    for (const auto& r : plan.rows)
      if (!r.memory_basis.empty() && std::find(shown.begin(), shown.end(), r.memory_basis) == shown.end()) {
        shown.push_back(r.memory_basis);
        out += "max memory, " + r.series + ": " +
               (std::isnan(r.memory_bytes) ? r.memory_basis : human_bytes(r.memory_bytes) + " from " + r.memory_basis) +
               "\n";
      }
    return out;
  }
  std::snprintf(line, sizeof line,
                "estimated wall time with %d workers x %d thread(s): %s (model: %.0f B/cell; time = cost ratio x "
                "iterations x cells x %.1e s, iterations %s)\n",
                plan.workers, plan.threads_per_worker, human_seconds(plan.wall_seconds).c_str(), kWorkerBytesPerCell,
                kSecondsPerCellIteration, iterations_model_text().c_str());
  out += line;
  for (const auto& [series, b] : bases) out += "cost ratio, largest grid of " + series + ": " + b + "\n";
  return out;
}

}  // namespace gridfree
