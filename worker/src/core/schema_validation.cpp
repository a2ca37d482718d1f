// Runs valijson on a document against an embedded schema and hands its raw
// results to explain_schema_errors (core/schema_messages.h) for readable,
// pointer-addressed problems.
//
// valijson reports through exceptions only when this is set before its headers.
#define VALIJSON_USE_EXCEPTIONS 1
// GCC 12 reports a false -Wrestrict inside std::string::replace as inlined
// into valijson's JSON-pointer code (a known GCC 12 false positive); it must be silenced
// before any standard header is read.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "core/schema_validation.h"

#include <map>
#include <memory>
#include <stdexcept>

#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "core/embedded_schemas.h"
#include "core/schema_messages.h"

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
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error("embedded schema '" + std::string(schema_name) + "' is not valid JSON: " + e.what());
  }
}

std::vector<Problem> validate_against_schema(const nlohmann::json& doc, std::string_view schema_name) {
  // Parsed schema documents by name, shared by valijson's $ref fetching and
  // by the message builder.
  std::map<std::string, nlohmann::json, std::less<>> documents;
  auto fetch = [&documents](std::string_view uri) -> const nlohmann::json& {
    std::string key(uri.substr(0, uri.find('#')));
    auto it = documents.find(key);
    if (it == documents.end()) it = documents.emplace(key, load_embedded_schema(key)).first;
    return it->second;
  };
  const nlohmann::json& root = fetch(std::string(schema_name));

  valijson::Schema schema;
  valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
  valijson::adapters::NlohmannJsonAdapter schema_adapter(root);
  parser.populateSchema(
      schema_adapter, schema,
      [&fetch](const std::string& uri) -> const nlohmann::json* {
        // valijson takes ownership of what it fetches and frees it below.
        return new nlohmann::json(fetch(uri));
      },
      [](const nlohmann::json* fetched) { delete fetched; });

  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter target(doc);
  if (validator.validate(schema, target, &results)) return {};

  std::vector<RawSchemaError> raw;
  for (const auto& error : results) {
    RawSchemaError r;
    // valijson's context is "<root>", then "[key]" / "[index]" per level.
    for (std::size_t i = 1; i < error.context.size(); ++i) {
      const std::string& c = error.context[i];
      r.path.push_back(c.size() >= 2 && c.front() == '[' && c.back() == ']' ? c.substr(1, c.size() - 2) : c);
    }
    r.description = error.description;
    raw.push_back(std::move(r));
  }
  return explain_schema_errors(raw, doc, root, fetch);
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
