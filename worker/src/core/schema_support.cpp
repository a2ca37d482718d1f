// SPDX-License-Identifier: GPL-3.0-or-later
// Checking that a schema uses only the implemented subset (core/schema_support.h).
#include "core/schema_support.h"

#include <set>
#include <string_view>
#include <utility>

#include "core/schema_pattern.h"

namespace gridfree {
namespace {

using nlohmann::json;

const std::set<std::string, std::less<>>& known_keywords() {
  static const std::set<std::string, std::less<>> keywords = {
      "type",      "properties",       "required",         "additionalProperties", "minProperties",
      "maxProperties", "enum",         "const",            "minimum",              "maximum",
      "exclusiveMinimum", "exclusiveMaximum", "minItems",  "maxItems",             "uniqueItems",
      "items",     "additionalItems",  "minLength",        "maxLength",            "pattern",
      "allOf",     "anyOf",            "oneOf",            "if",                   "then",
      "else",      "$ref",             "definitions",      "$schema",              "$id",
      "$comment",  "title",            "description",      "default",              "examples"};
  return keywords;
}

bool is_type_name(const json& t) {
  static const std::set<std::string, std::less<>> names = {"null",   "boolean", "integer", "number",
                                                           "string", "array",   "object"};
  return t.is_string() && names.count(t.get_ref<const std::string&>()) != 0;
}

bool is_count(const json& v) { return v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0); }

// Why the value of `keyword` is malformed, or empty.
std::string bad_value(const std::string& keyword, const json& v) {
  if (keyword == "type") {
    if (is_type_name(v)) return {};
    if (v.is_array() && !v.empty()) {
      for (const auto& t : v)
        if (!is_type_name(t)) return "unknown type name";
      return {};
    }
    return "unknown type name";
  }
  if (keyword == "required") {
    if (!v.is_array()) return "must be an array of strings";
    for (const auto& k : v)
      if (!k.is_string()) return "must be an array of strings";
    return {};
  }
  if (keyword == "enum") return v.is_array() && !v.empty() ? "" : "must be a non-empty array";
  if (keyword == "minimum" || keyword == "maximum" || keyword == "exclusiveMinimum" || keyword == "exclusiveMaximum")
    return v.is_number() ? "" : "must be a number (draft-07 form)";
  if (keyword == "minItems" || keyword == "maxItems" || keyword == "minLength" || keyword == "maxLength" ||
      keyword == "minProperties" || keyword == "maxProperties")
    return is_count(v) ? "" : "must be a non-negative integer";
  if (keyword == "uniqueItems") return v.is_boolean() ? "" : "must be a boolean";
  if (keyword == "$ref") return v.is_string() ? "" : "must be a string";
  if (keyword == "pattern") {
    if (!v.is_string()) return "must be a string";
    std::string why;
    return SchemaPattern::compile(v.get_ref<const std::string&>(), &why) ? "" : why;
  }
  if (keyword == "allOf" || keyword == "anyOf" || keyword == "oneOf")
    return v.is_array() && !v.empty() ? "" : "must be a non-empty array of schemas";
  if (keyword == "properties" || keyword == "definitions") return v.is_object() ? "" : "must be an object";
  return {};
}

std::string escape(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

}  // namespace

std::vector<std::string> unsupported_schema_parts(const json& schema) {
  std::vector<std::string> out;
  std::vector<std::pair<const json*, std::string>> stack = {{&schema, ""}};
  while (!stack.empty()) {
    auto [s, where] = stack.back();
    stack.pop_back();
    if (s->is_boolean()) continue;
    if (!s->is_object()) {
      out.push_back(where + ": a schema must be an object or a boolean");
      continue;
    }
    for (const auto& [keyword, value] : s->items()) {
      const std::string at = where + "/" + escape(keyword);
      if (known_keywords().count(keyword) == 0) {
        out.push_back(at + ": unsupported keyword");
        continue;
      }
      if (const std::string why = bad_value(keyword, value); !why.empty()) {
        out.push_back(at + ": " + why);
        continue;
      }
      if (keyword == "properties" || keyword == "definitions") {
        for (const auto& [name, sub] : value.items()) stack.emplace_back(&sub, at + "/" + escape(name));
      } else if (keyword == "allOf" || keyword == "anyOf" || keyword == "oneOf" ||
                 (keyword == "items" && value.is_array())) {
        for (std::size_t i = 0; i < value.size(); ++i) stack.emplace_back(&value[i], at + "/" + std::to_string(i));
      } else if (keyword == "additionalProperties" || keyword == "items" || keyword == "additionalItems" ||
                 keyword == "if" || keyword == "then" || keyword == "else") {
        stack.emplace_back(&value, at);
      }
    }
  }
  return out;
}

}  // namespace gridfree
