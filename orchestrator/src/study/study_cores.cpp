// SPDX-License-Identifier: GPL-3.0-or-later
// The study's cores rule against its grids (study/study_cores.h).
#include "study/study_cores.h"

#include <cmath>
#include <sstream>

#include "study/expression.h"
#include "study/job_cores.h"

namespace gridfree {
namespace {

std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// A problem when the value at `cells` is not a finite number; false then.
bool finite_at(const std::string& text, double cells, const std::string& which, ProblemList& problems) {
  double v = NAN;
  try {
    v = cores_value(text, cells);
  } catch (const ExpressionError& e) {
    problems.add_once("/cores", e.what());
    return false;
  }
  if (std::isfinite(v)) return true;
  problems.add_once("/cores", "'" + text + "' is " + number_text(v) + " at " + number_text(cells) + " cells (" + which +
                                  "); it must be a finite number");
  return false;
}

}  // namespace

void check_study_cores(const nlohmann::json& doc, const Study& s, ProblemList& problems) {
  const std::string text = study_cores_expression(doc);
  if (text.empty()) return;
  const std::size_t before = problems.problems().size();
  check_cores_expression(text, "/cores", problems);
  if (problems.problems().size() != before) return;
  const bool reads_cells = expression_names(text).count(kCoresVariable) != 0;
  for (const auto& c : s.cases) {
    if (c.external) {
      if (reads_cells && c.external->cells_expression.empty()) {
        problems.add_once("/cores", "'" + text + "' reads cells, but case '" + c.name +
                                        "' does not say how many cells its grids have (external/cells)");
        return;
      }
      const GridVariables& grids = external_grids_of(s, c.name);
      for (std::size_t g = 0; g < external_grid_count(grids); ++g) {
        const ExternalGrid grid = external_grid(*c.external, grids, g);
        const double cells = grid.cells ? std::max(1.0, std::round(*grid.cells)) : 1.0;
        if (!finite_at(text, cells, "case '" + c.name + "', grid " + std::to_string(g), problems)) return;
      }
      continue;
    }
    const auto grids = grids_for_case(s, c);
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const double cells = static_cast<double>(grids[g][0]) * grids[g][1] * grids[g][2];
      if (!finite_at(text, cells, "case '" + c.name + "', grid " + std::to_string(g), problems)) return;
    }
  }
}

}  // namespace gridfree
