// SPDX-License-Identifier: GPL-3.0-or-later
// Everything a study report shows, read from the store by the orchestrator
// and handed to the report writer (which never touches SQLite itself).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/self_check.h"
#include "report/alignment_data.h"

namespace gridfree {

// One job = one grid of one series.
struct GridPoint {
  std::string job_hash;
  double delta_star = 0;             // h
  int nx = 0, ny = 0, nz = 0;
  std::string status;                // result status: converged | not_converged | diverged | invalid | failed | (job) queued | running
  std::optional<double> dp_star;     // f, when the job produced one
  std::string reason;                // why not converged / failed
  std::string worker_outcome;        // the result's `outcome` word, '' for older results (report/stability_map.h)
  int remedy_from_iteration = 0;     // numerics.stall_remedy acted from this outer iteration (0: it did not)
  double wall_s = 0, cpu_s = 0, peak_rss_mb = 0;
  int iterations = 0;
};

// One (case, convection, fwhm_dp, drag[, deposition]) over all grids.
struct SeriesData {
  long long id = 0;
  std::string case_name, convection, drag, deposition;
  double fwhm_dp = 0;
  std::string status;                // queued | running | done | failed
  std::vector<GridPoint> grids;      // every grid of the series, any order
  std::optional<CoverageCheck> stored_coverage;  // made when the series finished (series.coverage_json)
  std::string label() const;         // "PC1 superbee fwhm6 bvk"; external: "cavity kinetic_energy"
  // External cases (docs/EXTERNAL.md): the quantity and how the report
  // names it and h; all "" for a physical case's dp*.
  std::string quantity{};
  std::string quantity_label{};      // "kinetic_energy: mean kinetic energy [m^2/s^2]"
  std::string h_label{};             // "h = 1 / N"
  std::map<std::string, std::string> levels{};  // the study's own factors' levels (external cases)
  // Axis titles: the quantity's, or DP*'s; h's meaning, or Δ*'s.
  std::string value_axis() const;
  std::string h_axis() const;
};

struct StudyReportData {
  std::string study_name;
  std::string status;
  std::string submitted_at, finished_at;
  std::string version;               // gridfree version that wrote the report
  std::string baseline_description;  // design (factorial / one_at_a_time baseline)
  std::string extrapolation_method = "averaged";  // averaged | capped | fm | eh14
  double p_low = 0.5, p_high = 2.1;  // power-law acceptance range
  std::optional<double> expected_order;  // the study's extrapolation.expected_order
  std::vector<std::string> generator_kinds;
  std::optional<double> target_rde;  // the study's grids.target_rde (adaptive grids), drawn on the RDE chart
  bool export_charts = true;         // PDF/PNG beside every SVG (report/chart_export.h)  // particle generators of the study's cases (report_about.h)
  std::vector<SeriesData> series;
  std::vector<std::string> adaptive_decisions;  // adaptive series: every decision in order (report/adaptive_section.h)
  std::vector<AlignmentGrid> alignment;  // the study's alignment check, if it has one (report_alignment.h)
  std::map<std::string, std::vector<std::string>> ensembles;  // name → instance cases (report_ensembles.h)
  std::map<std::string, nlohmann::json> beds;  // case → the "bed" of one of its results (store/store_beds.h, report/bed_about.h)
};

}  // namespace gridfree
