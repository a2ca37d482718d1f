// SPDX-License-Identifier: GPL-3.0-or-later
// adaptive_rungs (study/adaptive_rungs.h).
#include "study/adaptive_rungs.h"

#include "grid/grid.h"
#include "study/study_plan.h"

namespace gridfree {

std::vector<AdaptiveRung> adaptive_rungs(const std::vector<double>& ladder, const std::array<double, 3>& domain_dp) {
  std::vector<AdaptiveRung> out;
  for (double d : ladder) {
    AdaptiveRung r;
    r.delta_star = d;
    r.cells = cells_for_delta_star(domain_dp, d);
    r.model_cpu_s = estimated_seconds(r.cells, 1);
    r.memory_bytes = estimated_memory_bytes(r.cells);
    out.push_back(r);
  }
  return out;
}

}  // namespace gridfree
