// SPDX-License-Identifier: GPL-3.0-or-later
#include "job/case_grid.h"

namespace gridfree {

Grid make_grid(const CaseSpec& case_spec, const std::array<int, 3>& cells) {
  Grid g;
  g.n = cells;
  g.length = case_spec.domain_cm();
  for (int a = 0; a < 3; ++a) g.periodic[a] = case_spec.periodic(a);
  return g;
}

}  // namespace gridfree
