// SPDX-License-Identifier: GPL-3.0-or-later
// The worker's result document (docs/INTERFACE.md §2, schemas/result.schema.json).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gridfree {

enum class SolveStatus { kConverged, kNotConverged, kDiverged, kInvalid, kFailed };

std::string_view solve_status_name(SolveStatus s);  // "converged", ...
std::optional<SolveStatus> solve_status_from_name(std::string_view name);

struct JobResult {
  std::string job_hash;
  SolveStatus status = SolveStatus::kFailed;
  std::string reason;                       // empty when converged
  bool stalled = false;                     // not_converged: by the stall window (else the iteration cap)
  std::optional<double> dp_star;            // absent unless converged / a number exists
  std::array<int, 3> cells{};
  double delta_star = 0;
  int iterations = 0;
  double residual_continuity = 0;
  double residual_momentum = 0;
  double dp_star_change = 0;                // relative change of dp_star over the last check
  double wall_s = 0;
  double cpu_s = 0;
  double peak_rss_mb = 0;
  long particles = 0;
  double max_solids_fraction = 0;
  double mass_imbalance = 0;                // |Σ in − Σ out| / Σ in, mass flux
  nlohmann::json extra = nlohmann::json::object();  // more diagnostics (filter stats, timings per phase)
  nlohmann::json bed;                       // the bed's structure summary (particles/bed_summary.h); null: none
  std::string version;
};

// The result's outcome word (docs/INTERFACE.md §2 "outcome"): the status,
// with not_converged split into stalled and iteration_cap.
std::string_view result_outcome_name(const JobResult& r);

// The result document; non-finite numbers are written as null.
nlohmann::json to_json(const JobResult& r);
// Validates against schemas/result.schema.json, then reads; nulls become
// NaN (dp_star: absent). Throws InputError on a malformed document.
JobResult result_from_json(const nlohmann::json& j);

}  // namespace gridfree
