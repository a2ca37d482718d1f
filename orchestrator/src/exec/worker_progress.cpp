// SPDX-License-Identifier: GPL-3.0-or-later
// Reading the worker's progress file and the stop grace derived from it (see worker_progress.h).
#include "exec/worker_progress.h"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace gridfree {

std::filesystem::path progress_file(const std::filesystem::path& run_dir) { return run_dir / "progress.json"; }

std::optional<nlohmann::json> read_job_progress(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  auto j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  return j;
}

double stop_grace_seconds(double base_s, std::optional<double> longest_iteration_s) {
  if (!longest_iteration_s || !std::isfinite(*longest_iteration_s) || *longest_iteration_s <= 0) return base_s;
  return std::clamp(base_s + 1.5 * *longest_iteration_s, base_s, std::max(base_s, kMaxStopGraceSeconds));
}

double stop_grace_for_run(const std::filesystem::path& run_dir, double base_s) {
  const auto progress = read_job_progress(progress_file(run_dir));
  if (!progress) return base_s;
  const auto it = progress->find("longest_iteration_s");
  if (it == progress->end() || !it->is_number()) return base_s;
  return stop_grace_seconds(base_s, it->get<double>());
}

}  // namespace gridfree
