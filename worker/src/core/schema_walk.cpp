// Walking JSON Schemas alongside a document (core/schema_walk.h).
#include "core/schema_walk.h"

#include <algorithm>
#include <string>

namespace gridfree {
namespace {

using nlohmann::json;

bool has_type(const json& v, const std::string& type) {
  if (type == "null") return v.is_null();
  if (type == "boolean") return v.is_boolean();
  if (type == "integer") return v.is_number_integer();
  if (type == "number") return v.is_number();
  if (type == "string") return v.is_string();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  return false;
}

constexpr int kMaxDepth = 64;

}  // namespace

SchemaNode resolve_ref(const SchemaNode& n, const std::string& ref, const SchemaFetch& fetch) {
  const auto hash = ref.find('#');
  const std::string doc_part = ref.substr(0, hash);
  const std::string fragment = hash == std::string::npos ? std::string() : ref.substr(hash + 1);
  const json* doc = doc_part.empty() ? n.doc : &fetch(doc_part);
  const json* target = fragment.empty() ? doc : &doc->at(json::json_pointer(fragment));
  return {doc, target};
}

bool simple_match(const SchemaNode& n, const json& v, const SchemaFetch& fetch, int depth) {
  const json& s = *n.schema;
  if (s.is_boolean()) return s.get<bool>();
  if (!s.is_object() || depth > kMaxDepth) return true;
  if (auto it = s.find("$ref"); it != s.end() && it->is_string())
    return simple_match(resolve_ref(n, it->get<std::string>(), fetch), v, fetch, depth + 1);
  if (auto it = s.find("type"); it != s.end()) {
    bool ok = false;
    if (it->is_string()) ok = has_type(v, it->get<std::string>());
    else if (it->is_array())
      for (const auto& t : *it) ok = ok || (t.is_string() && has_type(v, t.get<std::string>()));
    if (!ok) return false;
  }
  if (auto it = s.find("const"); it != s.end() && v != *it) return false;
  if (auto it = s.find("enum"); it != s.end() && it->is_array() &&
      std::find(it->begin(), it->end(), v) == it->end())
    return false;
  if (auto it = s.find("required"); it != s.end() && it->is_array()) {
    if (!v.is_object()) return false;
    for (const auto& key : *it)
      if (key.is_string() && !v.contains(key.get<std::string>())) return false;
  }
  if (auto it = s.find("properties"); it != s.end() && it->is_object() && v.is_object()) {
    for (const auto& [key, sub] : it->items())
      if (v.contains(key) && !simple_match({n.doc, &sub}, v.at(key), fetch, depth + 1)) return false;
  }
  if (auto it = s.find("allOf"); it != s.end() && it->is_array())
    for (const auto& sub : *it)
      if (!simple_match({n.doc, &sub}, v, fetch, depth + 1)) return false;
  if (auto it = s.find("anyOf"); it != s.end() && it->is_array()) {
    bool any = false;
    for (const auto& sub : *it) any = any || simple_match({n.doc, &sub}, v, fetch, depth + 1);
    if (!any) return false;
  }
  if (auto it = s.find("oneOf"); it != s.end() && it->is_array()) {
    int count = 0;
    for (const auto& sub : *it) count += simple_match({n.doc, &sub}, v, fetch, depth + 1) ? 1 : 0;
    if (count != 1) return false;
  }
  return true;
}

namespace {

// Appends the subschemas applying to the value at path[idx..] below n.
void collect(const SchemaNode& n, const json* value, const std::vector<std::string>& path, std::size_t idx,
             const SchemaFetch& fetch, std::vector<SchemaNode>& out, int depth) {
  const json& s = *n.schema;
  if (depth > kMaxDepth) return;
  if (!s.is_object()) {
    if (idx == path.size()) out.push_back(n);
    return;
  }
  if (auto it = s.find("$ref"); it != s.end() && it->is_string()) {
    collect(resolve_ref(n, it->get<std::string>(), fetch), value, path, idx, fetch, out, depth + 1);
    return;
  }
  for (const char* combinator : {"allOf", "anyOf", "oneOf"}) {
    if (auto it = s.find(combinator); it != s.end() && it->is_array())
      for (const auto& sub : *it) collect({n.doc, &sub}, value, path, idx, fetch, out, depth + 1);
  }
  if (auto it = s.find("if"); it != s.end()) {
    const bool taken = value != nullptr && simple_match({n.doc, &*it}, *value, fetch, depth + 1);
    if (auto branch = s.find(taken ? "then" : "else"); branch != s.end())
      collect({n.doc, &*branch}, value, path, idx, fetch, out, depth + 1);
  }
  if (idx == path.size()) {
    out.push_back(n);
    return;
  }
  const std::string& token = path[idx];
  const json* child = nullptr;
  if (value != nullptr && value->is_object() && value->contains(token)) child = &value->at(token);
  const bool array_like = (value != nullptr && value->is_array()) || s.contains("items");
  if (array_like) {
    std::size_t index = 0;
    try {
      index = std::stoul(token);
    } catch (const std::exception&) {
      return;
    }
    if (value != nullptr && value->is_array() && index < value->size()) child = &value->at(index);
    if (auto items = s.find("items"); items != s.end()) {
      if (items->is_array()) {
        if (index < items->size()) collect({n.doc, &items->at(index)}, child, path, idx + 1, fetch, out, depth + 1);
        else if (auto extra = s.find("additionalItems"); extra != s.end())
          collect({n.doc, &*extra}, child, path, idx + 1, fetch, out, depth + 1);
      } else {
        collect({n.doc, &*items}, child, path, idx + 1, fetch, out, depth + 1);
      }
    }
    return;
  }
  if (auto props = s.find("properties"); props != s.end() && props->is_object() && props->contains(token)) {
    collect({n.doc, &props->at(token)}, child, path, idx + 1, fetch, out, depth + 1);
  } else if (auto extra = s.find("additionalProperties"); extra != s.end() && extra->is_object()) {
    collect({n.doc, &*extra}, child, path, idx + 1, fetch, out, depth + 1);
  }
}

}  // namespace

std::vector<SchemaNode> subschemas_at(const nlohmann::json& root_schema, const nlohmann::json& doc,
                                      const std::vector<std::string>& path, const SchemaFetch& fetch) {
  std::vector<SchemaNode> nodes;
  collect({&root_schema, &root_schema}, &doc, path, 0, fetch, nodes, 0);
  return nodes;
}

}  // namespace gridfree
