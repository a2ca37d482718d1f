// SPDX-License-Identifier: GPL-3.0-or-later
// The input of `gridfree-worker particles` (docs/INTERFACE.md §2,
// schemas/particles.schema.json): a domain and particle diameter plus a
// generator, or a file to convert, optionally boundaries and thermal
// particle velocities. Parsed into a CaseSpec whose `particles` is the
// source, so load_particles() does the rest.
//
// Boundaries default to periodic x and z (the paper's fixed beds), or walls
// for sscp_like (the SSCP-I bed); y is mass inflow below, outflow above.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/case_spec.h"

namespace gridfree {

// Validates (schema, then semantics: positive sizes, generator parameters,
// the file exists) and throws InputError naming every JSON path at fault.
CaseSpec parse_particles_spec(const nlohmann::json& doc, const std::filesystem::path& base_dir);

}  // namespace gridfree
