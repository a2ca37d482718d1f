// Readable schema problems from valijson's raw results (see schema_messages.h).
//
// For an error at document path P the schema is walked along P, collecting
// every subschema that applies to the value there; the failed keyword
// (enum, type, minimum, additionalProperties, ...) is looked up among them
// to word the reason with the schema's own values.
#include "core/schema_messages.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

#include "core/schema_validation.h"
#include "core/schema_walk.h"

namespace gridfree {
namespace {

using nlohmann::json;

std::string type_of(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "boolean";
  if (v.is_number_integer()) return "integer";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  return "object";
}

std::string show(const json& v) {
  if (!v.is_string()) return v.dump();
  std::string out(1, '\'');  // built by appending: GCC 12 warns falsely on "'" + std::string&&
  out += v.get_ref<const std::string&>();
  out += '\'';
  return out;
}

std::string join_values(const json& values, const std::string& sep) {
  std::string out;
  for (const auto& v : values) {
    if (!out.empty()) out += sep;
    out += v.is_string() ? v.get<std::string>() : v.dump();
  }
  return out;
}

std::string show_number(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

bool starts_with(const std::string& s, std::string_view prefix) { return s.rfind(prefix, 0) == 0; }

// valijson's messages that only say "something below failed".
bool is_wrapper(const std::string& d) {
  return starts_with(d, "Failed to validate against any schemas allowed by anyOf") ||
         starts_with(d, "Failed to validate against any child schemas allowed by oneOf") ||
         starts_with(d, "Failed to validate against a conditional schema") ||
         starts_with(d, "Failed to validate item #") ||
         starts_with(d, "Failed to validate against schema associated with") ||
         starts_with(d, "Failed to validate against additional properties schema") ||
         starts_with(d, "Failed to validate against dependent schema") ||
         starts_with(d, "Failed to validate against child schema");
}

bool is_prefix(const std::vector<std::string>& prefix, const std::vector<std::string>& path) {
  return prefix.size() <= path.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
}

// The bound named by a "minimum"-type keyword among the nodes, if any.
const json* find_keyword(const std::vector<SchemaNode>& nodes, const char* keyword) {
  for (const auto& n : nodes)
    if (n.schema->is_object())
      if (auto it = n.schema->find(keyword); it != n.schema->end()) return &*it;
  return nullptr;
}

class Explainer {
 public:
  Explainer(const json& doc, const json& root, const SchemaFetch& fetch) : doc_(doc), root_(root), fetch_(fetch) {}

  void explain(const RawSchemaError& e) {
    const std::string where = json_pointer_of(e.path);
    const json* value = value_at(e.path);
    const std::vector<SchemaNode> nodes = nodes_at(e.path);
    const std::string& d = e.description;

    if (starts_with(d, "Object contains a property that could not be validated")) {
      unknown_keys(e.path, value, nodes, d);
    } else if (starts_with(d, "Missing required property '")) {
      const std::string key = d.substr(27, d.rfind('\'') - 27);
      auto path = e.path;
      path.push_back(key);
      add(json_pointer_of(path), "required, but missing");
    } else if (starts_with(d, "Failed to match against any enum values") && value != nullptr) {
      const json* values = find_keyword(nodes, "enum");
      add(where, values ? show(*value) + " is not one of " + join_values(*values, ", ") : show(*value) + " is not allowed");
    } else if (starts_with(d, "Failed to match expected value set by 'const'") && value != nullptr) {
      const json* expected = find_keyword(nodes, "const");
      add(where, expected ? "must be " + show(*expected) + ", not " + show(*value) : show(*value) + " is not allowed");
    } else if (d.find("'type' constraint") != std::string::npos && value != nullptr) {
      const json* type = find_keyword(nodes, "type");
      const std::string expected = type ? (type->is_array() ? join_values(*type, " or ") : type->get<std::string>()) : "another type";
      add(where, "expected " + article(expected) + ", got " + article(type_of(*value)) + " (" + value->dump() + ")");
    } else if (starts_with(d, "Expected number") && value != nullptr && value->is_number()) {
      add(where, bound_reason(d, *value, nodes));
    } else if (starts_with(d, "Array should contain no fewer than") && value != nullptr) {
      const json* n = find_keyword(nodes, "minItems");
      add(where, "needs at least " + (n ? n->dump() : std::string("more")) + " items, has " + std::to_string(value->size()));
    } else if (starts_with(d, "Array should contain no more than") && value != nullptr) {
      const json* n = find_keyword(nodes, "maxItems");
      add(where, "allows at most " + (n ? n->dump() : std::string("fewer")) + " items, has " + std::to_string(value->size()));
    } else if (starts_with(d, "Failed to match regex") && value != nullptr) {
      const json* pattern = find_keyword(nodes, "pattern");
      add(where, show(*value) + " does not match the pattern " + (pattern ? pattern->get<std::string>() : std::string("required")));
    } else if (starts_with(d, "String should be no fewer than")) {
      add(where, "must not be empty");
    } else if (d.find("violate uniqueness") != std::string::npos) {
      add(where, "items must be unique (" + d.substr(0, d.find(" violate")) + " are equal)");
    } else {
      add(where, d);
    }
  }

  std::vector<Problem> take() { return std::move(problems_); }

 private:
  const json* value_at(const std::vector<std::string>& path) const {
    const json* v = &doc_;
    for (const auto& token : path) {
      if (v->is_object() && v->contains(token)) {
        v = &v->at(token);
      } else if (v->is_array()) {
        std::size_t i = 0;
        try {
          i = std::stoul(token);
        } catch (const std::exception&) {
          return nullptr;
        }
        if (i >= v->size()) return nullptr;
        v = &v->at(i);
      } else {
        return nullptr;
      }
    }
    return v;
  }

  std::vector<SchemaNode> nodes_at(const std::vector<std::string>& path) const {
    return subschemas_at(root_, doc_, path, fetch_);
  }

  // Every key of the object that some applicable schema with
  // additionalProperties: false does not list (valijson names only the first).
  void unknown_keys(const std::vector<std::string>& path, const json* value, const std::vector<SchemaNode>& nodes,
                    const std::string& description) {
    bool found = false;
    if (value != nullptr && value->is_object()) {
      for (const auto& n : nodes) {
        const json& s = *n.schema;
        if (!s.is_object() || s.value("additionalProperties", json(true)) != json(false)) continue;
        const json props = s.value("properties", json::object());
        for (const auto& [key, unused] : value->items()) {
          if (props.contains(key)) continue;
          auto key_path = path;
          key_path.push_back(key);
          std::vector<std::string> allowed;
          for (const auto& [name, sub] : props.items()) allowed.push_back(name);
          std::string list;
          for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
          add(json_pointer_of(key_path), "unknown key" + (list.empty() ? std::string() : " (allowed: " + list + ")"));
          found = true;
        }
      }
    }
    if (!found) {
      // Fall back on the key valijson names.
      const auto open = description.rfind(": '");
      auto key_path = path;
      if (open != std::string::npos) key_path.push_back(description.substr(open + 3, description.size() - open - 5));
      add(json_pointer_of(key_path), "unknown key");
    }
  }

  static std::string article(const std::string& type) {
    if (type.empty()) return type;
    const bool vowel = std::string("aeio").find(type[0]) != std::string::npos;
    return (vowel ? "an " : "a ") + type;
  }

  static std::string bound_reason(const std::string& d, const json& value, const std::vector<SchemaNode>& nodes) {
    const bool greater = d.find("greater") != std::string::npos;
    const bool or_equal = d.find("or equal") != std::string::npos;
    const char* keyword = greater ? (or_equal ? "minimum" : "exclusiveMinimum") : (or_equal ? "maximum" : "exclusiveMaximum");
    const json* bound = find_keyword(nodes, keyword);
    std::string limit = bound && bound->is_number() ? show_number(bound->get<double>()) : d.substr(d.rfind(' ') + 1);
    return "must be " + std::string(greater ? ">" : "<") + (or_equal ? "= " : " ") + limit + ", got " + value.dump();
  }

  void add(std::string where, std::string reason) {
    if (seen_.insert({where, reason}).second) problems_.push_back({std::move(where), std::move(reason)});
  }

  const json& doc_;
  const json& root_;
  const SchemaFetch& fetch_;
  std::vector<Problem> problems_;
  std::set<std::pair<std::string, std::string>> seen_;
};

}  // namespace

std::vector<Problem> explain_schema_errors(const std::vector<RawSchemaError>& errors, const json& doc,
                                           const json& root_schema, const SchemaFetch& fetch) {
  Explainer explainer(doc, root_schema, fetch);
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const RawSchemaError& e = errors[i];
    if (is_wrapper(e.description)) {
      // Keep a wrapper only when nothing more specific lies at or below it.
      const bool covered = std::any_of(errors.begin(), errors.end(), [&](const RawSchemaError& other) {
        return !is_wrapper(other.description) && is_prefix(e.path, other.path);
      });
      if (covered) continue;
    }
    explainer.explain(e);
  }
  return explainer.take();
}

}  // namespace gridfree
