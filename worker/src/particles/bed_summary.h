// SPDX-License-Identifier: GPL-3.0-or-later
// The compact summary of a bed's structure that a job's result carries
// (docs/INTERFACE.md §2 "bed", docs/PARTICLES.md "Structure"), made from
// bed_structure(): what the study report's "About this case" shows per case.
//
// - particles, the bed's height (top of the highest sphere) and its ε_s
//   (solid volume / (cross-section × that height));
// - the largest S(k)/N over all particles and over the core, each with its
//   axis and period, and `ordered`: the core peak reaches kOrderedPeak = 0.05
//   (a random packing gives S/N of order 1/N, a crystal of order 1; the
//   all-particle peak also sees wall and floor layering, so it is shown but
//   not used for the flag);
// - g(r): the contact peak (value, r) and g at √3 d and 2 d;
// - the range of the 1-d slab ε_s(y) over the slabs lying entirely between
//   2 d above the lowest sphere's bottom and 2 d below the highest top
//   (none when the bed is thinner than that);
// - local ε_s (cubes of ≈ 3 d): mean and standard deviation.
#pragma once

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "particles/bed_structure.h"

namespace gridfree {

inline constexpr double kOrderedPeak = 0.05;  // S/N in the core at which a bed counts as ordered

// The summary of `s`, measured on `particles` in a box of `length_cm`.
nlohmann::json bed_summary(const BedStructure& s, const std::vector<Particle>& particles,
                           const std::array<double, 3>& length_cm);

}  // namespace gridfree
