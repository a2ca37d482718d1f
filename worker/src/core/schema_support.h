// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON-Schema (draft-07) subset the validator implements, and the check
// that a schema stays inside it.
//
// Supported keywords: type, properties, required, additionalProperties,
// minProperties, maxProperties, enum, const, minimum, maximum,
// exclusiveMinimum, exclusiveMaximum (numbers, as in draft-07), minItems,
// maxItems, uniqueItems, items (one schema, or the tuple form with
// additionalItems), minLength, maxLength, pattern (core/schema_pattern.h),
// allOf, anyOf, oneOf, if/then/else, $ref (core/schema_refs.h), definitions.
// Annotations without effect: $schema, $id, $comment, title, description,
// default, examples.
//
// A schema using any other keyword is refused, so that no constraint is
// silently ignored (tests/unit/core walks every shipped schema).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

// Descriptions ("/definitions/x/foo: unsupported keyword") of everything in
// `schema` outside the subset above; empty when the schema is supported.
// Walks the schema with an explicit stack (no recursion).
std::vector<std::string> unsupported_schema_parts(const nlohmann::json& schema);

}  // namespace gridfree
