// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON-Schema keyword checks (core/schema_keywords.h) on small inline
// schemas: each keyword accepts what draft-07 accepts, rejects what it
// rejects, and reports at the pointer of the offending value.
#include <gtest/gtest.h>

#include <string>

#include "core/schema_keywords.h"
#include "core/schema_messages.h"

namespace gridfree {
namespace {

using nlohmann::json;

std::vector<Problem> check(const json& schema, const json& doc) {
  const SchemaFetch fetch = [](std::string_view) -> const json& { throw std::runtime_error("no other documents"); };
  SchemaChecker checker(fetch);
  return checker.validate({&schema, &schema}, doc);
}

std::string only(const json& schema, const json& doc) {
  const auto problems = check(schema, doc);
  EXPECT_EQ(problems.size(), 1u) << format_problems(problems);
  return problems.empty() ? std::string() : problems.front().where + ": " + problems.front().reason;
}

TEST(SchemaKeywords, Type) {
  const json s = {{"type", "integer"}};
  EXPECT_TRUE(check(s, 3).empty());
  EXPECT_EQ(only(s, 2.0), ": expected an integer, got a number (2.0)");  // strict integers
  EXPECT_EQ(only({{"type", {"string", "null"}}}, json::array({1})), ": expected a string or null, got an array");
  EXPECT_TRUE(check({{"type", {"string", "null"}}}, nullptr).empty());
}

TEST(SchemaKeywords, EnumAndConst) {
  EXPECT_EQ(only({{"enum", {"a", "b"}}}, "c"), ": 'c' is not one of a, b");
  EXPECT_TRUE(check({{"enum", {1, "b"}}}, 1.0).empty());  // numbers compare by value
  EXPECT_EQ(only({{"const", "wall"}}, "open"), ": must be 'wall', not 'open'");
}

TEST(SchemaKeywords, NumericBounds) {
  const json s = {{"minimum", 0}, {"exclusiveMaximum", 1}};
  EXPECT_TRUE(check(s, 0).empty());
  EXPECT_EQ(only(s, 1), ": must be < 1, got 1");
  EXPECT_EQ(only(s, -0.5), ": must be >= 0, got -0.5");
  EXPECT_EQ(only({{"exclusiveMinimum", 0}}, 0), ": must be > 0, got 0");
  EXPECT_EQ(only({{"maximum", 2.5}}, 3), ": must be <= 2.5, got 3");
  EXPECT_TRUE(check({{"minimum", 0}}, "text").empty());  // bounds apply to numbers only
}

TEST(SchemaKeywords, StringsCountCharactersAndQuoteAShortPrefix) {
  EXPECT_EQ(only({{"minLength", 1}}, ""), ": must not be empty");
  EXPECT_TRUE(check({{"maxLength", 2}}, "\xc3\xa9\xc3\xa9").empty());  // two characters, four bytes
  const std::string long_name(30000, 'x');
  const std::string reason = only({{"maxLength", 10}, {"enum", {"a"}}}, long_name);
  EXPECT_LT(reason.size(), 120u) << reason;
  EXPECT_NE(reason.find("(30000 bytes)"), std::string::npos) << reason;
}

TEST(SchemaKeywords, PatternOnLongStringsIsLinear) {
  const json s = {{"pattern", "^[A-Za-z0-9][A-Za-z0-9._-]*$"}};
  EXPECT_TRUE(check(s, "bursting-bubble_2.v1").empty());
  EXPECT_EQ(check(s, "-x").size(), 1u);
  EXPECT_EQ(check(s, "a b").size(), 1u);
  EXPECT_TRUE(check(s, std::string(200000, 'a')).empty());  // std::regex overflowed its stack here
  EXPECT_EQ(check(s, std::string(200000, 'a') + "!").size(), 1u);
  EXPECT_TRUE(check({{"pattern", "b+c"}}, "aabbbcd").empty());  // unanchored: a match anywhere
  EXPECT_EQ(check({{"pattern", "^ab?c$"}}, "abbc").size(), 1u);
  EXPECT_TRUE(check({{"pattern", "^ab?c$"}}, "ac").empty());
}

TEST(SchemaKeywords, Arrays) {
  const json s = {{"minItems", 2}, {"maxItems", 3}, {"uniqueItems", true}, {"items", {{"type", "number"}}}};
  EXPECT_TRUE(check(s, {1, 2}).empty());
  EXPECT_EQ(only(s, {1}), ": needs at least 2 items, has 1");
  EXPECT_EQ(only(s, {1, 2, 3, 4}), ": allows at most 3 items, has 4");
  EXPECT_EQ(only(s, {1, 2, 1}), "/2: duplicates item 0 (items must be unique)");
  EXPECT_EQ(only(s, {1, "x"}), "/1: expected a number, got a string ('x')");
  const json tuple = {{"items", {{{"type", "string"}}, {{"type", "integer"}}}}, {"additionalItems", false}};
  EXPECT_TRUE(check(tuple, {"a", 1}).empty());
  EXPECT_EQ(only(tuple, {"a", 1, 2}), "/2: not allowed here");
  EXPECT_EQ(only(tuple, {1, 1}), "/0: expected a string, got an integer (1)");
}

TEST(SchemaKeywords, ObjectsNameEveryUnknownAndMissingKey) {
  const json s = {{"type", "object"},
                  {"required", {"a", "b"}},
                  {"properties", {{"a", {{"type", "integer"}}}, {"b", true}}},
                  {"additionalProperties", false}};
  EXPECT_TRUE(check(s, {{"a", 1}, {"b", "anything"}}).empty());
  const auto problems = check(s, {{"a", 1}, {"x/y", 1}, {"z", 2}});
  ASSERT_EQ(problems.size(), 3u) << format_problems(problems);
  EXPECT_EQ(problems[0].where, "/b");
  EXPECT_EQ(problems[0].reason, "required, but missing");
  EXPECT_EQ(problems[1].where, "/x~1y");
  EXPECT_EQ(problems[1].reason, "unknown key (allowed: a, b)");
  EXPECT_EQ(problems[2].where, "/z");
  EXPECT_EQ(only({{"minProperties", 1}}, json::object()), ": needs at least 1 entry, has 0");
  EXPECT_EQ(only({{"additionalProperties", {{"type", "string"}}}}, {{"k", 1}}), "/k: expected a string, got an integer (1)");
}

// A hostile 30,000-character key is quoted by its first 40 characters, at
// its object (a pointer would echo it whole).
TEST(SchemaKeywords, AnUnknownLongKeyIsQuotedShort) {
  const json s = {{"type", "object"}, {"properties", {{"a", true}}}, {"additionalProperties", false}};
  const std::string key(30000, 'k');
  const auto problems = check(s, {{"a", 1}, {key, 1}});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].where, "");
  EXPECT_EQ(problems[0].reason, "unknown key '" + std::string(kQuotedPrefix, 'k') + "...' (30000 bytes) (allowed: a)");
  EXPECT_LT(format_problems(problems).size(), 200u);
  EXPECT_EQ(check(s, {{std::string(kQuotedPrefix, 'k'), 1}})[0].where, "/" + std::string(kQuotedPrefix, 'k'));
}

TEST(SchemaKeywords, CombinatorsAndConditions) {
  const json cond = {{"if", {{"properties", {{"kind", {{"const", "a"}}}}}, {"required", {"kind"}}}},
                     {"then", {{"required", {"x"}}}},
                     {"else", {{"required", {"y"}}}}};
  EXPECT_EQ(only(cond, {{"kind", "a"}}), "/x: required, but missing");
  EXPECT_EQ(only(cond, {{"kind", "b"}}), "/y: required, but missing");
  const json all = {{"allOf", {{{"minimum", 0}}, {{"maximum", 1}}}}};
  EXPECT_EQ(only(all, 2), ": must be <= 1, got 2");
  const json any = {{"anyOf", {{{"type", "string"}}, {{"type", "integer"}, {"minimum", 5}}}}};
  EXPECT_TRUE(check(any, "s").empty());
  EXPECT_TRUE(check(any, 7).empty());
  EXPECT_EQ(only(any, 3), ": must be >= 5, got 3");
  const json one = {{"oneOf", {{{"type", "integer"}}, {{"minimum", 0}}}}};
  EXPECT_TRUE(check(one, -1).empty());
  EXPECT_TRUE(check(one, 0.5).empty());
  EXPECT_EQ(only(one, 1), ": matches more than one of the allowed forms (1 and 2)");
}

TEST(SchemaKeywords, RefsResolveAndCyclesStop) {
  const json s = {{"definitions", {{"pos", {{"exclusiveMinimum", 0}}}, {"loop", {{"$ref", "#/definitions/loop"}}}}},
                  {"properties", {{"a", {{"$ref", "#/definitions/pos"}}}, {"b", {{"$ref", "#/definitions/loop"}}}}}};
  EXPECT_EQ(only(s, {{"a", 0}}), "/a: must be > 0, got 0");
  const auto problems = check(s, {{"b", 1}});  // a $ref cycle ends at the depth limit, not in a crash
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].reason.find("nested deeper"), std::string::npos);
  EXPECT_THROW(check({{"$ref", "#/definitions/none"}}, 1), std::runtime_error);
}

TEST(SchemaKeywords, DeepDocumentsStopAtTheDepthLimit) {
  // An array nested beyond the limit, under a schema that recurses into items.
  const json s = {{"definitions", {{"n", {{"items", {{"$ref", "#/definitions/n"}}}}}}}, {"$ref", "#/definitions/n"}};
  json doc = json::array();
  for (int i = 0; i < 1000; ++i) doc = json::array({std::move(doc)});
  const auto problems = check(s, doc);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].reason.find("nested deeper"), std::string::npos);
  // Dismantle iteratively: nlohmann's destructor would also recurse (fine at 1000).
}

}  // namespace
}  // namespace gridfree
