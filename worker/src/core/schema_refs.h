// SPDX-License-Identifier: GPL-3.0-or-later
// "$ref" resolution for the embedded JSON Schemas (core/schema_validation.h).
//
// A reference is "#/definitions/x" within the current schema document or
// "other.schema.json#/definitions/x" into another embedded document; the
// fragment is an RFC 6901 pointer. Only these local and embedded references
// exist: nothing is fetched from outside the program.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace gridfree {

// Resolves a schema document by name ("job.schema.json"); the reference stays
// valid for the duration of a validation. Throws std::runtime_error for an
// unknown name.
using SchemaFetch = std::function<const nlohmann::json&(std::string_view name)>;

struct SchemaNode {
  const nlohmann::json* doc;     // the schema document the node belongs to ($ref base)
  const nlohmann::json* schema;  // the subschema itself (object or boolean)
};

// The node `ref` points to from n. Throws std::runtime_error when the target
// does not exist (a broken shipped schema is an internal error).
SchemaNode resolve_ref(const SchemaNode& n, const std::string& ref, const SchemaFetch& fetch);

}  // namespace gridfree
