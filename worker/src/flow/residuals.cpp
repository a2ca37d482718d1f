// Reference mass flux of the continuity residual (residuals.h).
#include "flow/residuals.h"

#include <algorithm>
#include <cmath>

#include "flow/mass_flux.h"
#include "flow/parallel.h"

namespace gridfree {

double continuity_reference(const FlowProblem& problem, const FaceVector& mass_flux) {
  const BoundaryFlux bf = boundary_mass_flux(problem, mass_flux);
  if (bf.in > 0) return bf.in;
  double ref = 0;
  for (int a = 0; a < 3; ++a) {
    const auto& F = mass_flux[a].values;
    const double total = deterministic_sum(F.size(), [&F](std::size_t f) { return std::abs(F[f]); });
    ref = std::max(ref, total / mass_flux[a].layout.n[a]);
  }
  return ref;
}

}  // namespace gridfree
