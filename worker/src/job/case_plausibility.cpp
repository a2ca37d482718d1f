// SPDX-License-Identifier: GPL-3.0-or-later
// Physical plausibility of a case (job/case_plausibility.h).
#include "job/case_plausibility.h"

#include <cmath>

#include "core/json_fields.h"
#include "core/text.h"

namespace gridfree {
namespace {

void check_range(double x, PlausibleRange r, const std::string& where, const char* what, ProblemList& problems) {
  if (!(x > 0)) return;  // sign errors are reported by the schema and parse_case
  if (!(x >= r.low && x <= r.high))
    problems.add(where, std::string(what) + " " + number_text(x) + " is outside the plausible range [" +
                            number_text(r.low) + ", " + number_text(r.high) + "] (docs/LIMITS.md)");
}

}  // namespace

void check_geometry_plausibility(const std::array<double, 3>& domain_dp, double particle_diameter_cm,
                                 const std::string& path, ProblemList& problems) {
  check_range(particle_diameter_cm, kParticleDiameterRange, child_pointer(path, "particle_diameter_cm"),
              "particle diameter", problems);
  for (std::size_t a = 0; a < 3; ++a)
    check_range(domain_dp[a], kDomainRange, child_pointer(child_pointer(path, "domain_dp"), a), "domain size",
                problems);
}

void check_case_plausibility(const CaseSpec& c, const std::string& path, ProblemList& problems) {
  const std::string gas = child_pointer(path, "gas");
  check_range(c.gas.density_g_cm3, kGasDensityRange, child_pointer(gas, "density_g_cm3"), "gas density", problems);
  check_range(c.gas.viscosity_g_cm_s, kGasViscosityRange, child_pointer(gas, "viscosity_g_cm_s"), "gas viscosity",
              problems);
  check_geometry_plausibility(c.domain_dp, c.particle_diameter_cm, path, problems);
  for (std::size_t a = 0; a < 3; ++a)
    if (!(std::abs(c.gravity_cm_s2[a]) <= kMaxGravity))
      problems.add(child_pointer(child_pointer(path, "gravity_cm_s2"), a),
                   "gravity component " + number_text(c.gravity_cm_s2[a]) + " exceeds " + number_text(kMaxGravity) +
                       " cm/s² in magnitude (docs/LIMITS.md)");

  const std::string y_low = child_pointer(child_pointer(path, "boundaries"), "y_low");
  const BoundarySpec& inflow = c.boundaries[1][0];
  if (inflow.kind != BoundaryKind::kMassInflow) {
    problems.add(y_low, "dp* needs a mass_inflow with a superficial velocity > 0 at y_low (docs/PHYSICS.md §7)");
  } else if (!(inflow.superficial_velocity_cm_s > 0)) {
    problems.add(child_pointer(y_low, "superficial_velocity_cm_s"),
                 "the inflow velocity must be > 0: dp* is normalised by it (docs/PHYSICS.md §7)");
  } else {
    check_range(inflow.superficial_velocity_cm_s, kInflowRange, child_pointer(y_low, "superficial_velocity_cm_s"),
                "inflow velocity", problems);
  }
}

}  // namespace gridfree
