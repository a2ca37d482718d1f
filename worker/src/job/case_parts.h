// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of a case object, parsed one at a time (used by parse_case and
// by the `particles` command's spec, whose particle source sits at the top
// level). Every reader takes the JSON pointer of its object and adds
// problems instead of throwing.
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/case_spec.h"
#include "core/input_error.h"

namespace gridfree {

using CaseBoundaries = std::array<std::array<BoundarySpec, 2>, 3>;

// {"x": "periodic"|"wall", "z": ..., "y_low": "wall"|{...}, "y_high": ...}.
// mass_inflow only at y_low, pressure_outflow only at y_high.
CaseBoundaries parse_boundaries(const nlohmann::json& obj, const std::string& where, ProblemList& problems);

// The object holding exactly one of "generator", "file" (+ "format") or
// "uniform". Relative files resolve against base_dir and must exist.
ParticleSource parse_particle_source(const nlohmann::json& obj, const std::string& where,
                                     const std::filesystem::path& base_dir, ProblemList& problems);

ParticleVelocitySpec parse_particle_velocity(const nlohmann::json& obj, const std::string& where,
                                             ProblemList& problems);

// Domain sizes > 0 (problems at where/i).
void check_domain(const std::array<double, 3>& domain_dp, const std::string& where, ProblemList& problems);

}  // namespace gridfree
