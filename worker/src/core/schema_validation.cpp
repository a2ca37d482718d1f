// SPDX-License-Identifier: GPL-3.0-or-later
// Validation against the embedded schemas (core/schema_validation.h): finds
// the schema documents, checks them against the implemented subset and runs
// the keyword checks (core/schema_keywords.h).
#include "core/schema_validation.h"

#include <map>
#include <stdexcept>

#include "core/embedded_schemas.h"
#include "core/schema_keywords.h"
#include "core/schema_support.h"

namespace gridfree {
namespace {

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// Embedded text for "job.schema.json", "job.schema" or "job" (whichever
// name the build registered), or an empty view.
std::string_view find_schema_text(std::string_view name) {
  std::string_view base = name;
  if (const auto hash = base.find('#'); hash != std::string_view::npos) base = base.substr(0, hash);
  if (const auto slash = base.find_last_of('/'); slash != std::string_view::npos) base = base.substr(slash + 1);
  if (ends_with(base, ".json")) base.remove_suffix(5);
  if (auto text = embedded_schema(base); !text.empty()) return text;
  if (ends_with(base, ".schema")) {
    base.remove_suffix(7);
    if (auto text = embedded_schema(base); !text.empty()) return text;
  } else {
    if (auto text = embedded_schema(std::string(base) + ".schema"); !text.empty()) return text;
  }
  return {};
}

}  // namespace

nlohmann::json load_embedded_schema(std::string_view schema_name) {
  const std::string_view text = find_schema_text(schema_name);
  if (text.empty()) throw std::runtime_error("no embedded schema named '" + std::string(schema_name) + "'");
  nlohmann::json schema;
  try {
    schema = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("embedded schema '" + std::string(schema_name) + "' is not valid JSON: " + e.what());
  }
  if (const auto parts = unsupported_schema_parts(schema); !parts.empty())
    throw std::runtime_error("embedded schema '" + std::string(schema_name) +
                             "' is outside the supported JSON-Schema subset: " + parts.front());
  return schema;
}

std::vector<Problem> validate_against_schema(const nlohmann::json& doc, std::string_view schema_name) {
  // Parsed schema documents by name, for cross-file $refs.
  std::map<std::string, nlohmann::json, std::less<>> documents;
  const SchemaFetch fetch = [&documents](std::string_view uri) -> const nlohmann::json& {
    std::string key(uri.substr(0, uri.find('#')));
    auto it = documents.find(key);
    if (it == documents.end()) it = documents.emplace(key, load_embedded_schema(key)).first;
    return it->second;
  };
  const nlohmann::json& root = fetch(schema_name);
  SchemaChecker checker(fetch);
  return checker.validate({&root, &root}, doc);
}

std::string json_pointer_of(const std::vector<std::string>& tokens) {
  std::string out;
  for (const auto& t : tokens) {
    out += '/';
    for (char c : t) {
      if (c == '~') out += "~0";
      else if (c == '/') out += "~1";
      else out += c;
    }
  }
  return out;
}

}  // namespace gridfree
