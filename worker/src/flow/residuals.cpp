// SPDX-License-Identifier: GPL-3.0-or-later
// Reference mass flux of the continuity residual (residuals.h).
#include "flow/residuals.h"

#include <cmath>

#include "flow/parallel.h"

namespace gridfree {

double continuity_reference(const FaceVector& mass_flux) {
  double ref = 0;
  for (int a = 0; a < 3; ++a) {
    const auto& F = mass_flux[a].values;
    ref += deterministic_sum(F.size(), [&F](std::size_t f) { return std::abs(F[f]); });
  }
  return ref;
}

}  // namespace gridfree
