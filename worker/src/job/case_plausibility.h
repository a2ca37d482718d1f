// SPDX-License-Identifier: GPL-3.0-or-later
// Physical plausibility of a case, checked before any work starts (by the
// worker's parse_case and so by `gridfree validate` as well). The ranges are
// wide on purpose: they refuse what cannot be a gas-solid CFD-DEM case or
// would break the arithmetic, never an unusual but real one. Reasons in
// docs/LIMITS.md ("Physical ranges").
#pragma once

#include <array>
#include <string>

#include "core/case_spec.h"
#include "core/input_error.h"

namespace gridfree {

struct PlausibleRange {
  double low, high;  // inclusive
};

inline constexpr PlausibleRange kGasDensityRange{1e-6, 20.0};        // g/cm³: rarefied gas .. dense liquid
inline constexpr PlausibleRange kGasViscosityRange{1e-7, 1e3};       // g/(cm s): below any gas .. heavy oils
inline constexpr PlausibleRange kParticleDiameterRange{1e-5, 10.0};  // cm: 0.1 µm .. 10 cm
inline constexpr PlausibleRange kDomainRange{1.0, 1e5};              // particle diameters per direction
inline constexpr PlausibleRange kInflowRange{1e-6, 1e5};             // cm/s: > 0 .. 1 km/s (incompressible model)
inline constexpr double kMaxGravity = 1e6;                           // cm/s² per component (1000 g)

// Domain sizes (particle diameters) and the particle diameter within their
// ranges (also used by the `particles` command's spec).
void check_geometry_plausibility(const std::array<double, 3>& domain_dp, double particle_diameter_cm,
                                 const std::string& path, ProblemList& problems);

// Adds a problem at path/<field> for every value of `c` outside its range,
// and when the case has no mass inflow at y_low (dp* is normalised by the
// inflow velocity, docs/PHYSICS.md §7, so there would be nothing to compute).
void check_case_plausibility(const CaseSpec& c, const std::string& path, ProblemList& problems);

}  // namespace gridfree
