// SPDX-License-Identifier: GPL-3.0-or-later
// Wording of schema problems (used by core/schema_keywords.cpp), kept in one
// place so every reason reads the same way and stays short: a value is
// quoted only up to a short prefix, and arrays / objects are described by
// their size, never printed (a hostile document may be huge or deep).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace gridfree {

// At most this many characters of a string value are quoted in a message.
inline constexpr std::size_t kQuotedPrefix = 40;

// JSON Schema type name of a value: null, boolean, integer, number, string, array, object.
std::string schema_type_of(const nlohmann::json& v);

// "'abc'", "'abcd...' (30000 characters)", "1.5", "true", "an array of 3 items", "an object with 2 keys".
std::string show_value(const nlohmann::json& v);

// "an integer", "a string", "a number or null" (type names from a schema's "type").
std::string with_article(const std::string& type);

// The "type" keyword's value in words: "integer", "number or null".
std::string type_names(const nlohmann::json& type);

// Schema values joined for a message: "fou, central, minmod" (strings unquoted).
std::string join_values(const nlohmann::json& values, const std::string& separator);

// A bound of the schema as written: 0, 1, 1e-08.
std::string show_bound(const nlohmann::json& bound);

}  // namespace gridfree
