// SPDX-License-Identifier: GPL-3.0-or-later
// Grid-design warnings (see grid_design.h).
#include "extrap/grid_design.h"

#include <algorithm>
#include "extrap/value_format.h"
#include "extrap/verdict.h"

namespace gridfree {

std::vector<std::string> grid_design_warnings(const std::vector<double>& h, bool particle_bed) {
  std::vector<std::string> out;
  const VerdictRules rules;
  const int n = static_cast<int>(h.size());
  if (n - 3 < rules.min_dof)
    out.push_back(std::to_string(n) + " grid(s) leave " + std::to_string(std::max(0, n - 3)) +
                  " degree(s) of freedom for the 3-parameter fit: at least " + std::to_string(3 + rules.min_dof) +
                  " grids are needed for a converged verdict");
  if (particle_bed && !h.empty() && *std::min_element(h.begin(), h.end()) > kAsymptoticDeltaStar) {
    const std::string limit = format_significant(kAsymptoticDeltaStar);
    out.push_back("every grid is coarser than Δ* = " + limit + " (finest " +
                  format_cell_size(*std::min_element(h.begin(), h.end())) +
                  "): the series is likely pre-asymptotic; add grids with Δ* ≤ " + limit);
  }
  return out;
}

}  // namespace gridfree
