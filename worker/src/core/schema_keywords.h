// SPDX-License-Identifier: GPL-3.0-or-later
// The keyword checks of the JSON-Schema validator (subset in
// core/schema_support.h; entry point core/schema_validation.h).
//
// check() applies one subschema to one value and records a Problem, at the
// JSON pointer of the offending value, for every keyword that fails:
//   type          "expected an integer, got a string ('many')"
//   enum / const  "'superbe' is not one of fou, central, ..."
//   minimum ...   "must be > 0, got -200"
//   required      at the missing key: "required, but missing"
//   additionalProperties: false   at each extra key: "unknown key (allowed: ...)"; a key longer than
//                                 kQuotedPrefix at its object, quoted by show_value
//   pattern, min/maxLength, min/maxItems, uniqueItems (at the later duplicate)
// Combinators report what lies below them: allOf all of its branches,
// if/then/else the branch the value takes, anyOf/oneOf the problems of the
// closest branch (fewest problems) when none matches.
//
// The walk recurses once per schema level it enters; it stops with a problem
// after kMaxSchemaDepth levels, so neither a deep document nor a $ref cycle
// can exhaust the stack (documents are limited to a smaller nesting depth by
// the readers, core/json_limits.h).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "core/schema_refs.h"

namespace gridfree {

inline constexpr int kMaxSchemaDepth = 256;

class SchemaChecker {
 public:
  explicit SchemaChecker(const SchemaFetch& fetch) : fetch_(fetch) {}

  // Problems of `doc` against `root`, at most one per JSON pointer (the first found).
  std::vector<Problem> validate(const SchemaNode& root, const nlohmann::json& doc);

 private:
  void check(const SchemaNode& n, const nlohmann::json& v, int depth);
  bool passes(const SchemaNode& n, const nlohmann::json& v, int depth);
  void check_number(const nlohmann::json& s, const nlohmann::json& v);
  void check_string(const nlohmann::json& s, const nlohmann::json& v);
  void check_array(const SchemaNode& n, const nlohmann::json& v, int depth);
  void check_object(const SchemaNode& n, const nlohmann::json& v, int depth);
  void check_combinators(const SchemaNode& n, const nlohmann::json& v, int depth);
  void check_alternatives(const SchemaNode& n, const nlohmann::json& branches, const nlohmann::json& v, int depth,
                          bool exactly_one);
  void add(std::string reason);
  void add_at(const std::string& key, std::string reason);

  const SchemaFetch& fetch_;
  std::vector<std::string> path_;  // keys / indices from the document root to the value in check()
  std::vector<Problem>* out_ = nullptr;
};

}  // namespace gridfree
