// Job identity: SHA-256 of the canonical job JSON + the solver version.
//
// Canonical JSON: object keys sorted, no whitespace, every number written as
// a double in shortest round-trip form (so 20 and 20.0 hash alike).
// numerics.deposition is hashed expanded (presets and defaults written out,
// job/deposition_parse.cpp), so a preset and its explicit spelling are one job.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gridfree {

std::string sha256_hex(std::string_view data);
std::string canonical_json(const nlohmann::json& j);
std::string job_hash(const nlohmann::json& job_doc);  // uses kSolverVersion

}  // namespace gridfree
