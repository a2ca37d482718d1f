// SPDX-License-Identifier: GPL-3.0-or-later
// The keyword checks of the JSON-Schema validator (core/schema_keywords.h).
#include "core/schema_keywords.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "core/command_suggestion.h"
#include "core/schema_messages.h"
#include "core/schema_pattern.h"
#include "core/schema_validation.h"

namespace gridfree {
namespace {

using nlohmann::json;

bool has_type(const json& v, const std::string& type) {
  if (type == "null") return v.is_null();
  if (type == "boolean") return v.is_boolean();
  if (type == "integer") return v.is_number_integer();  // strict: 2.0 is a number, not an integer
  if (type == "number") return v.is_number();
  if (type == "string") return v.is_string();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  return false;
}

bool type_matches(const json& type, const json& v) {
  if (type.is_string()) return has_type(v, type.get_ref<const std::string&>());
  return std::any_of(type.begin(), type.end(), [&](const json& t) { return has_type(v, t.get<std::string>()); });
}

// Number of UTF-8 characters (JSON Schema lengths count characters, not bytes).
std::size_t utf8_length(const std::string& s) {
  return static_cast<std::size_t>(
      std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

const json* keyword(const json& s, const char* name) {
  const auto it = s.find(name);
  return it == s.end() ? nullptr : &*it;
}

}  // namespace

std::vector<Problem> SchemaChecker::validate(const SchemaNode& root, const json& doc) {
  std::vector<Problem> raw;
  out_ = &raw;
  path_.clear();
  check(root, doc, 0);
  out_ = nullptr;
  std::vector<Problem> problems;
  std::set<std::string> seen;
  for (auto& p : raw)
    if (seen.insert(p.where).second) problems.push_back(std::move(p));
  return problems;
}

void SchemaChecker::add(std::string reason) { out_->push_back({json_pointer_of(path_), std::move(reason)}); }

void SchemaChecker::add_at(const std::string& key, std::string reason) {
  path_.push_back(key);
  add(std::move(reason));
  path_.pop_back();
}

bool SchemaChecker::passes(const SchemaNode& n, const json& v, int depth) {
  std::vector<Problem> scratch;
  std::vector<Problem>* saved = std::exchange(out_, &scratch);
  check(n, v, depth);
  out_ = saved;
  return scratch.empty();
}

void SchemaChecker::check(const SchemaNode& n, const json& v, int depth) {
  const json& s = *n.schema;
  if (s.is_boolean()) {
    if (!s.get<bool>()) add("not allowed here");
    return;
  }
  if (depth > kMaxSchemaDepth) {
    add("nested deeper than " + std::to_string(kMaxSchemaDepth) + " schema levels");
    return;
  }
  if (const json* ref = keyword(s, "$ref")) {  // draft-07: $ref replaces its siblings
    check(resolve_ref(n, ref->get<std::string>(), fetch_), v, depth + 1);
    return;
  }
  if (const json* type = keyword(s, "type"); type && !type_matches(*type, v)) {
    std::string got = with_article(schema_type_of(v));
    if (v.is_primitive()) got += " (" + show_value(v) + ")";
    add("expected " + with_article(type_names(*type)) + ", got " + got);
    return;  // the other keywords would only repeat the mismatch
  }
  if (const json* expected = keyword(s, "const"); expected && v != *expected)
    add("must be " + show_value(*expected) + ", not " + show_value(v));
  if (const json* values = keyword(s, "enum"); values && std::find(values->begin(), values->end(), v) == values->end())
    add(show_value(v) + " is not one of " + join_values(*values, ", "));
  if (v.is_number()) check_number(s, v);
  if (v.is_string()) check_string(s, v);
  if (v.is_array()) check_array(n, v, depth);
  if (v.is_object()) check_object(n, v, depth);
  check_combinators(n, v, depth);
}

void SchemaChecker::check_number(const json& s, const json& v) {
  const double x = v.get<double>();
  const auto bound = [&](const char* name, bool ok_if_greater, bool inclusive) {
    const json* b = keyword(s, name);
    if (b == nullptr) return;
    const double limit = b->get<double>();
    const bool ok = ok_if_greater ? (inclusive ? x >= limit : x > limit) : (inclusive ? x <= limit : x < limit);
    if (!ok)
      add(std::string("must be ") + (ok_if_greater ? ">" : "<") + (inclusive ? "= " : " ") + show_bound(*b) +
          ", got " + v.dump());
  };
  bound("minimum", true, true);
  bound("exclusiveMinimum", true, false);
  bound("maximum", false, true);
  bound("exclusiveMaximum", false, false);
}

void SchemaChecker::check_string(const json& s, const json& v) {
  const auto& text = v.get_ref<const std::string&>();
  const std::size_t length = utf8_length(text);
  if (const json* n = keyword(s, "minLength"); n && length < n->get<std::size_t>())
    add(n->get<std::size_t>() == 1 ? "must not be empty" : "needs at least " + n->dump() + " characters, has " +
                                                               std::to_string(length));
  if (const json* n = keyword(s, "maxLength"); n && length > n->get<std::size_t>())
    add("allows at most " + n->dump() + " characters, has " + std::to_string(length));
  if (const json* p = keyword(s, "pattern")) {
    std::string why;
    const auto pattern = SchemaPattern::compile(p->get<std::string>(), &why);
    if (pattern && !pattern->matches(text))
      add(show_value(v) + " does not match the pattern " + p->get<std::string>());
  }
}

void SchemaChecker::check_array(const SchemaNode& n, const json& v, int depth) {
  const json& s = *n.schema;
  if (const json* k = keyword(s, "minItems"); k && v.size() < k->get<std::size_t>())
    add("needs at least " + k->dump() + (k->get<std::size_t>() == 1 ? " item" : " items") + ", has " +
        std::to_string(v.size()));
  if (const json* k = keyword(s, "maxItems"); k && v.size() > k->get<std::size_t>())
    add("allows at most " + k->dump() + " items, has " + std::to_string(v.size()));
  if (const json* k = keyword(s, "uniqueItems"); k && k->get<bool>()) {
    std::map<json, std::size_t> first;  // O(n log n); json's order is total
    for (std::size_t i = 0; i < v.size(); ++i) {
      const auto [it, inserted] = first.emplace(v[i], i);
      if (!inserted) add_at(std::to_string(i), "duplicates item " + std::to_string(it->second) + " (items must be unique)");
    }
  }
  const json* items = keyword(s, "items");
  if (items == nullptr) return;
  const json* extra = keyword(s, "additionalItems");
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json* sub = items->is_array() ? (i < items->size() ? &(*items)[i] : extra) : items;
    if (sub == nullptr) continue;
    path_.push_back(std::to_string(i));
    check({n.doc, sub}, v[i], depth + 1);
    path_.pop_back();
  }
}

void SchemaChecker::check_object(const SchemaNode& n, const json& v, int depth) {
  const json& s = *n.schema;
  if (const json* required = keyword(s, "required"))
    for (const auto& key : *required)
      if (!v.contains(key.get<std::string>())) add_at(key.get<std::string>(), "required, but missing");
  if (const json* k = keyword(s, "minProperties"); k && v.size() < k->get<std::size_t>())
    add("needs at least " + k->dump() + (k->get<std::size_t>() == 1 ? " entry" : " entries") + ", has " +
        std::to_string(v.size()));
  if (const json* k = keyword(s, "maxProperties"); k && v.size() > k->get<std::size_t>())
    add("allows at most " + k->dump() + " entries, has " + std::to_string(v.size()));
  const json* props = keyword(s, "properties");
  const json* extra = keyword(s, "additionalProperties");
  for (const auto& [key, value] : v.items()) {
    const json* sub = props && props->contains(key) ? &props->at(key) : extra;
    if (sub == nullptr) continue;
    if (sub->is_boolean() && !sub->get<bool>() && sub == extra) {
      std::string allowed;
      std::vector<std::string> names;
      if (props)
        for (const auto& [name, unused] : props->items()) {
          allowed += (allowed.empty() ? "" : ", ") + name;
          names.push_back(name);
        }
      const std::string near = nearest_name(key, names);
      const std::string reason = "unknown key" + (near.empty() ? std::string() : "; did you mean '" + near + "'?") +
                                 (allowed.empty() ? std::string() : " (allowed: " + allowed + ")");
      if (key.size() <= kQuotedPrefix) add_at(key, reason);
      else add(reason.substr(0, 11) + " " + show_value(key) + reason.substr(11));  // at the object: a pointer would echo it whole
      continue;
    }
    path_.push_back(key);
    check({n.doc, sub}, value, depth + 1);
    path_.pop_back();
  }
}

void SchemaChecker::check_combinators(const SchemaNode& n, const json& v, int depth) {
  const json& s = *n.schema;
  if (const json* all = keyword(s, "allOf"))
    for (const auto& sub : *all) check({n.doc, &sub}, v, depth + 1);
  if (const json* any = keyword(s, "anyOf")) check_alternatives(n, *any, v, depth, false);
  if (const json* one = keyword(s, "oneOf")) check_alternatives(n, *one, v, depth, true);
  if (const json* condition = keyword(s, "if")) {
    const json* branch = keyword(s, passes({n.doc, condition}, v, depth + 1) ? "then" : "else");
    if (branch) check({n.doc, branch}, v, depth + 1);
  }
}

void SchemaChecker::check_alternatives(const SchemaNode& n, const json& branches, const json& v, int depth,
                                       bool exactly_one) {
  std::vector<std::vector<Problem>> results(branches.size());
  std::vector<std::size_t> matching;
  std::vector<Problem>* saved = out_;
  for (std::size_t i = 0; i < branches.size(); ++i) {
    out_ = &results[i];
    check({n.doc, &branches[i]}, v, depth + 1);
    if (results[i].empty()) matching.push_back(i);
  }
  out_ = saved;
  if (matching.size() == 1 || (!exactly_one && !matching.empty())) return;
  if (matching.size() > 1) {
    add("matches more than one of the allowed forms (" + std::to_string(matching[0] + 1) + " and " +
        std::to_string(matching[1] + 1) + ")");
    return;
  }
  // None matches: the problems of the closest form say what to change; a
  // form of the value's own type is closer than any form of another type.
  const auto distance = [&](std::size_t i) {
    const json* type = branches[i].is_object() ? keyword(branches[i], "type") : nullptr;
    return results[i].size() + (type && !type_matches(*type, v) ? std::size_t{1000000} : 0);
  };
  std::size_t closest = 0;
  for (std::size_t i = 1; i < branches.size(); ++i)
    if (distance(i) < distance(closest)) closest = i;
  out_->insert(out_->end(), results[closest].begin(), results[closest].end());
}

}  // namespace gridfree
