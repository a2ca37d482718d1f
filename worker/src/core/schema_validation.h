// SPDX-License-Identifier: GPL-3.0-or-later
// Validation of JSON documents against the embedded JSON Schemas (schemas/).
//
// The project's own validator of a JSON-Schema draft-07 subset
// (core/schema_support.h lists the keywords; core/schema_keywords.h the
// checks) reports one Problem per offending value, each with the JSON pointer
// of that value ("/numerics/convection") and a readable reason ("'superbe' is
// not one of fou, central, ..."). Every schema is checked against the subset
// when loaded, so no constraint of a schema is silently ignored.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// Problems of `doc` against the embedded schema `schema_name` ("job.schema",
// "study.schema", "result.schema", "particles.schema"; a trailing ".json" is
// accepted). Empty when the document is valid. Cross-file "$ref"s
// ("job.schema.json#/definitions/case") resolve to other embedded schemas.
// Throws std::runtime_error if the schema itself is missing, broken or uses
// a keyword outside the subset.
std::vector<Problem> validate_against_schema(const nlohmann::json& doc, std::string_view schema_name);

// The parsed embedded schema (same names as above), checked against the
// subset. Throws std::runtime_error when there is no such schema or it is
// outside the subset.
nlohmann::json load_embedded_schema(std::string_view schema_name);

// RFC 6901 pointer of a path of keys / indices: {"case", "domain_dp", "0"} -> "/case/domain_dp/0".
std::string json_pointer_of(const std::vector<std::string>& tokens);

}  // namespace gridfree
