// Turns valijson's raw results into readable problems (used by
// core/schema_validation.cpp; separate so the wording rules are in one place).
//
// Each raw error carries the path of the value it is about and valijson's
// generic description ("Failed to match against any enum values."). The
// schema is walked along that path (through $ref, allOf/anyOf/oneOf, and the
// branch of if/then/else the value takes) to find the constraint that
// failed, which gives the specific reason ("'superbe' is not one of fou,
// central, ..."). Wrapper errors of combinators are dropped when a more
// specific error lies at or below them; duplicates are merged.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

struct RawSchemaError {
  std::vector<std::string> path;  // keys / array indices from the document root
  std::string description;        // valijson's wording
};

// Resolves a schema document by URI ("job.schema.json"); the reference stays valid.
using SchemaFetch = std::function<const nlohmann::json&(std::string_view uri)>;

std::vector<Problem> explain_schema_errors(const std::vector<RawSchemaError>& errors,
                                           const nlohmann::json& doc, const nlohmann::json& root_schema,
                                           const SchemaFetch& fetch);

}  // namespace gridfree
