// Validation of JSON documents against the embedded JSON Schemas (schemas/).
//
// valijson decides whether a document is valid; its nested results are then
// flattened into one Problem per offending value, each with the JSON pointer
// of that value ("/numerics/convection") and a readable reason ("'superbe' is
// not one of fou, central, ..."). Combinator noise (anyOf/oneOf/if-then-else
// wrappers) is dropped in favour of the most specific messages.
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
// Throws std::runtime_error if the schema itself is missing or broken.
std::vector<Problem> validate_against_schema(const nlohmann::json& doc, std::string_view schema_name);

// The parsed embedded schema (same names as above). Throws std::runtime_error
// when there is no such schema.
nlohmann::json load_embedded_schema(std::string_view schema_name);

// RFC 6901 pointer of a path of keys / indices: {"case", "domain_dp", "0"} -> "/case/domain_dp/0".
std::string json_pointer_of(const std::vector<std::string>& tokens);

}  // namespace gridfree
