// SPDX-License-Identifier: GPL-3.0-or-later
// external_rungs (study/external_rungs.h).
#include "study/external_rungs.h"

#include <algorithm>
#include <cmath>

#include "study/case_extends.h"
#include "study/external_ladder.h"
#include "study/external_plan.h"
#include "study/format_number.h"

namespace gridfree {

ExternalRungs external_rungs(const nlohmann::json& definition, const AdaptiveGrids& settings,
                             const std::string& case_name, const nlohmann::json& first_spec,
                             const CostHistory& measured) {
  ExternalRungs out;
  if (!settings.variable) return out;
  ProblemList ignored;  // the study was validated when it was submitted
  const nlohmann::json resolved = resolve_case_extends(definition, ignored);
  const nlohmann::json ext = resolved.value(nlohmann::json::json_pointer("/cases/" + case_name + "/external"),
                                            nlohmann::json::object());
  const ExternalCase c = external_expressions(ext);
  const ExternalLadder ladder = external_ladder(c, *settings.variable, settings.ratio, case_name, ignored);
  const GridVariables& grids = ladder.variables;
  for (std::size_t k = 0; k < ladder.h_nominal.size(); ++k) {
    const ExternalGrid g = external_grid(c, grids, k);
    nlohmann::json spec = first_spec;
    nlohmann::json variables = nlohmann::json::object();
    for (const auto& [n, v] : g.variables) variables[n] = v;
    spec["case"]["external"]["variables"] = variables;
    nlohmann::json grid = {{"level", k}, {"h", g.h}};
    if (g.cells) grid["cells"] = *g.cells;
    spec["numerics"]["grid"] = grid;
    AdaptiveRung r;
    r.delta_star = ladder.h_nominal[k];
    const double cells = g.cells ? std::max(1.0, std::round(*g.cells)) : 1.0;
    r.cells = {static_cast<int>(std::min(cells, 2.0e9)), 1, 1};
    const ExternalJobCost cost = external_job_cost(c, spec, cells, measured);
    r.model_cpu_s = cost.cpu_s;
    r.memory_bytes = cost.memory_bytes;
    r.label = settings.variable->name + " = " + format_number("%.6g", grids.at(settings.variable->name)[k]) +
              (g.cells ? ", " + format_number("%.6g", cells) + " cells" : std::string());
    out.rungs.push_back(r);
    out.specs.push_back(std::move(spec));
    out.h.push_back(g.h);
  }
  return out;
}

}  // namespace gridfree
