// Walking JSON Schemas alongside a document, to find which subschemas
// apply to a value (core/schema_messages.cpp words its problems with them).
//
// From the root, the walk follows the document path through properties /
// additionalProperties / items, resolves "$ref" (also into other embedded
// schema documents), enters every branch of allOf/anyOf/oneOf, and for
// if/then/else only the branch the value takes. The `if` test understands
// the keywords this project's schemas use in conditions: type, const, enum,
// required, properties, allOf/anyOf/oneOf, $ref (others count as met).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/schema_messages.h"

namespace gridfree {

struct SchemaNode {
  const nlohmann::json* doc;     // the schema document the node belongs to ($ref base)
  const nlohmann::json* schema;  // the subschema itself (object or boolean)
};

// "#/definitions/x" within n's document, or "other.json#/..." via fetch.
SchemaNode resolve_ref(const SchemaNode& n, const std::string& ref, const SchemaFetch& fetch);

// Whether `v` meets the subschema (subset of keywords, see above).
bool simple_match(const SchemaNode& n, const nlohmann::json& v, const SchemaFetch& fetch, int depth = 0);

// Every subschema that applies to the value at `path` of `doc`.
std::vector<SchemaNode> subschemas_at(const nlohmann::json& root_schema, const nlohmann::json& doc,
                                      const std::vector<std::string>& path, const SchemaFetch& fetch);

}  // namespace gridfree
