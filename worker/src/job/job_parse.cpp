// SPDX-License-Identifier: GPL-3.0-or-later
// parse_numerics and parse_job (job/job_spec.h): schema validation first
// (schemas/job.schema.json, every problem with its JSON pointer), then the
// semantic checks, all collected into one InputError (each problem once,
// none inside a value the schema could not read: core/follow_on_problems.h).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/follow_on_problems.h"
#include "core/json_fields.h"
#include "core/schema_validation.h"
#include "core/text.h"
#include "grid/grid.h"
#include "job/job_spec.h"

namespace gridfree {

std::string_view deposition_kind_name(DepositionKind kind) {
  return kind == DepositionKind::kDiffusion ? "diffusion" : "centroid";
}

std::string_view filter_diffusivity_name(FilterDiffusivity d) {
  switch (d) {
    case FilterDiffusivity::kSeed: return "seed";
    case FilterDiffusivity::kMfix: return "mfix";
    case FilterDiffusivity::kConsistent: return "consistent";
  }
  return "?";
}

NumericsSpec parse_numerics(const nlohmann::json& j, const std::string& path, const std::array<double, 3>& domain_dp,
                            ProblemList& problems) {
  NumericsSpec n;
  if (!j.is_object()) {
    problems.add(path, "numerics must be an object");
    return n;
  }

  // Grid: cells per direction, or Δ* → round(L*/Δ*) (at least 1).
  const std::string grid_at = child_pointer(path, "grid");
  const auto& grid = read_object(j, "grid", path, problems, true);
  if (grid.contains("cells")) {
    const auto& cells = grid.at("cells");
    if (!cells.is_array() || cells.size() != 3) {
      problems.add(child_pointer(grid_at, "cells"), "expected [nx, ny, nz]");
    } else {
      for (std::size_t a = 0; a < 3; ++a) {
        const auto& c = cells[a];
        if (!c.is_number_integer() || c.get<std::int64_t>() < 1 || c.get<std::int64_t>() > 1000000)
          problems.add(child_pointer(child_pointer(grid_at, "cells"), a), "must be an integer from 1 to 1000000");
        else
          n.cells[a] = static_cast<int>(c.get<std::int64_t>());
      }
    }
  } else {
    const double delta_star = read_number(grid, "delta_star", grid_at, problems);
    if (!(delta_star > 0)) {
      problems.add(child_pointer(grid_at, "delta_star"), "must be > 0");
    } else {
      bool domain_ok = true;
      for (double l : domain_dp) domain_ok = domain_ok && l > 0 && l / delta_star < 1e6;
      if (domain_ok) n.cells = cells_for_delta_star(domain_dp, delta_star);
      else problems.add(child_pointer(grid_at, "delta_star"), "gives no valid grid for this domain");
    }
  }
  const double total = static_cast<double>(n.cells[0]) * n.cells[1] * n.cells[2];
  if (total > 2e9) problems.add(grid_at, "more than 2e9 cells");
  // The pressure drop is taken along y, from the inflow to the outlet: one
  // cell there has no drop to resolve (docs/LIMITS.md "Grids and memory").
  if (n.cells[1] >= 1 && n.cells[1] < kMinFlowCells)
    problems.add(grid_at, "gives " + std::to_string(n.cells[1]) + " cell along y, the flow direction; at least " +
                              std::to_string(kMinFlowCells) + " are needed (a smaller delta_star or more cells)");

  const std::string convection = read_string(j, "convection", path, problems);
  if (auto l = limiter_from_name(convection)) n.convection = *l;
  else if (!convection.empty())
    problems.add(child_pointer(path, "convection"), "'" + convection + "' is not one of " + limiter_names());
  const std::string drag = read_string(j, "drag", path, problems);
  if (auto d = drag_law_from_name(drag)) n.drag = *d;
  else if (!drag.empty()) problems.add(child_pointer(path, "drag"), "'" + drag + "' is not one of " + drag_law_names());

  const std::string dep_at = child_pointer(path, "deposition");
  n.deposition = parse_deposition(read_object(j, "deposition", path, problems, true), dep_at, problems);
  // A filter wider than the whole domain smooths the bed to its mean.
  const double largest_dp = std::max({domain_dp[0], domain_dp[1], domain_dp[2]});
  if (largest_dp > 0 && n.deposition.fwhm_dp > largest_dp)
    problems.add(child_pointer(dep_at, "fwhm_dp"),
                 "the filter width " + number_text(n.deposition.fwhm_dp) +
                     " d_p exceeds the domain's largest extent " + number_text(largest_dp) +
                     " d_p; give at most that (docs/LIMITS.md)");

  const std::string tol_at = child_pointer(path, "tolerances");
  const auto& tol = read_object(j, "tolerances", path, problems);
  const TolerancesSpec defaults;
  n.tolerances.linear = read_number(tol, "linear", tol_at, problems, defaults.linear);
  n.tolerances.filter = read_number(tol, "filter", tol_at, problems, defaults.filter);
  n.tolerances.steady = read_number(tol, "steady", tol_at, problems, defaults.steady);
  for (const auto& [key, value] : {std::pair{"linear", n.tolerances.linear}, std::pair{"filter", n.tolerances.filter},
                                   std::pair{"steady", n.tolerances.steady}})
    if (!(value > 0 && value < 1)) problems.add(child_pointer(tol_at, key), "must be in (0, 1)");

  const std::int64_t iterations = read_integer(j, "max_iterations", path, problems, 20000);
  if (iterations < 1 || iterations > 1000000000) problems.add(child_pointer(path, "max_iterations"), "must be from 1 to 1e9");
  else n.max_iterations = static_cast<int>(iterations);
  const std::int64_t window = read_integer(j, "stall_window", path, problems, 0);
  if (window < 0 || window > 1000000000) problems.add(child_pointer(path, "stall_window"), "must be from 0 (off) to 1e9");
  else n.stall_window = static_cast<int>(window);
  const std::string remedy = read_string(j, "stall_remedy", path, problems, std::string("none"));
  if (remedy == "relax_correction") n.relax_stalled_correction = true;
  else if (remedy != "none")
    problems.add(child_pointer(path, "stall_remedy"), "'" + remedy + "' is not one of none, relax_correction");
  if (n.relax_stalled_correction && n.stall_window == 0)
    problems.add(child_pointer(path, "stall_remedy"), "relax_correction acts when the stall rule fires: it needs a stall_window above 0");
  return n;
}

JobSpec parse_job(const nlohmann::json& doc, const std::filesystem::path& base_dir) {
  const std::vector<Problem> schema_problems = validate_against_schema(doc, "job.schema");
  ProblemList problems;
  problems.append(schema_problems);
  JobSpec job;
  const bool parts = doc.is_object() && doc.contains("case") && doc["case"].is_object() && doc.contains("numerics") &&
                     doc["numerics"].is_object();
  if (!parts) throw InputError(schema_problems);
  try {
    // The semantic checks run on a document the schema refused too, so
    // independent problems are reported together.
    job.case_spec = parse_case(doc.at("case"), "/case", base_dir, problems);
    job.numerics = parse_numerics(doc.at("numerics"), "/numerics", job.case_spec.domain_dp, problems);
  } catch (const InputError& e) {
    problems.append(e.problems());
  } catch (const std::exception&) {
    if (schema_problems.empty()) throw;  // a value of the wrong type the schema reported stops the checks there
  }
  if (!problems.empty()) throw InputError(without_follow_ons(problems.problems()));
  job.source = doc;
  // Record (and hash) the expanded transfer: a preset and its explicit spelling are one job.
  job.source["numerics"]["deposition"] = deposition_json(job.numerics.deposition, doc["numerics"]["deposition"]);
  return job;
}

JobSpec parse_job_file(const std::filesystem::path& file) {
  const nlohmann::json doc = read_json_file(file);
  return parse_job(doc, file.has_parent_path() ? file.parent_path() : std::filesystem::path("."));
}

}  // namespace gridfree
