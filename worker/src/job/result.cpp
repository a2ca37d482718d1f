// SPDX-License-Identifier: GPL-3.0-or-later
// The result document (docs/INTERFACE.md §2, schemas/result.schema.json).
#include "job/result.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.h"
#include "core/schema_validation.h"

namespace gridfree {
namespace {

constexpr std::array<std::pair<SolveStatus, std::string_view>, 5> kStatusNames{{
    {SolveStatus::kConverged, "converged"},
    {SolveStatus::kNotConverged, "not_converged"},
    {SolveStatus::kDiverged, "diverged"},
    {SolveStatus::kInvalid, "invalid"},
    {SolveStatus::kFailed, "failed"},
}};

nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

double number_at(const nlohmann::json& j, const char* object, const char* key, double fallback = 0) {
  if (!j.contains(object) || !j.at(object).contains(key)) return fallback;
  const auto& v = j.at(object).at(key);
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::string_view solve_status_name(SolveStatus s) {
  for (const auto& [status, name] : kStatusNames)
    if (status == s) return name;
  return "failed";
}

std::optional<SolveStatus> solve_status_from_name(std::string_view name) {
  for (const auto& [status, n] : kStatusNames)
    if (n == name) return status;
  return std::nullopt;
}

std::string_view result_outcome_name(const JobResult& r) {
  if (r.status == SolveStatus::kNotConverged) return r.stalled ? "stalled" : "iteration_cap";
  return solve_status_name(r.status);
}

nlohmann::json to_json(const JobResult& r) {
  // A converged result always carries its dp*: the worker refuses cases
  // without inflow (job/case_plausibility.h), so this is a program error.
  if (r.status == SolveStatus::kConverged && !(r.dp_star && std::isfinite(*r.dp_star)))
    throw std::logic_error("a converged result without a finite dp_star");
  nlohmann::json j;
  j["schema"] = "gridfree/result/1";
  j["job_hash"] = r.job_hash;
  j["status"] = solve_status_name(r.status);
  j["outcome"] = result_outcome_name(r);
  if (!r.reason.empty()) j["reason"] = r.reason;
  j["srq"] = {{"dp_star", r.dp_star ? number_or_null(*r.dp_star) : nlohmann::json(nullptr)}};
  j["grid"] = {{"cells", r.cells}, {"delta_star", std::isfinite(r.delta_star) ? r.delta_star : 0.0}};
  j["iterations"] = r.iterations;
  j["residuals"] = {{"continuity", number_or_null(r.residual_continuity)},
                    {"momentum", number_or_null(r.residual_momentum)},
                    {"dp_star_change", number_or_null(r.dp_star_change)}};
  j["timing"] = {{"wall_s", r.wall_s}, {"cpu_s", r.cpu_s}};
  j["memory"] = {{"peak_rss_mb", r.peak_rss_mb}};
  j["diagnostics"] = {{"particles", r.particles},
                      {"max_solids_fraction", number_or_null(r.max_solids_fraction)},
                      {"mass_imbalance", number_or_null(r.mass_imbalance)}};
  if (r.extra.is_object() && !r.extra.empty()) j["extra"] = r.extra;
  if (r.bed.is_object()) j["bed"] = r.bed;
  j["version"] = r.version;
  return j;
}

JobResult result_from_json(const nlohmann::json& j) {
  const std::vector<Problem> problems = validate_against_schema(j, "result.schema");
  if (!problems.empty()) throw InputError(problems);
  JobResult r;
  r.job_hash = j.at("job_hash").get<std::string>();
  r.status = solve_status_from_name(j.at("status").get<std::string>()).value_or(SolveStatus::kFailed);
  r.reason = j.value("reason", "");
  r.stalled = j.value("outcome", "") == "stalled";
  if (j.contains("srq") && j.at("srq").contains("dp_star") && j.at("srq").at("dp_star").is_number())
    r.dp_star = j.at("srq").at("dp_star").get<double>();
  if (j.contains("grid") && j.at("grid").contains("cells"))
    for (std::size_t a = 0; a < 3; ++a) r.cells[a] = j.at("grid").at("cells").at(a).get<int>();
  r.delta_star = number_at(j, "grid", "delta_star");
  r.iterations = j.value("iterations", 0);
  r.residual_continuity = number_at(j, "residuals", "continuity");
  r.residual_momentum = number_at(j, "residuals", "momentum");
  r.dp_star_change = number_at(j, "residuals", "dp_star_change");
  r.wall_s = number_at(j, "timing", "wall_s");
  r.cpu_s = number_at(j, "timing", "cpu_s");
  r.peak_rss_mb = number_at(j, "memory", "peak_rss_mb");
  if (j.contains("diagnostics") && j.at("diagnostics").contains("particles"))
    r.particles = j.at("diagnostics").at("particles").get<long>();
  r.max_solids_fraction = number_at(j, "diagnostics", "max_solids_fraction");
  r.mass_imbalance = number_at(j, "diagnostics", "mass_imbalance");
  if (j.contains("extra")) r.extra = j.at("extra");
  if (j.contains("bed")) r.bed = j.at("bed");
  r.version = j.at("version").get<std::string>();
  return r;
}

}  // namespace gridfree
