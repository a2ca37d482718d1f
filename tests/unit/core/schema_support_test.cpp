// SPDX-License-Identifier: GPL-3.0-or-later
// The implemented JSON-Schema subset (core/schema_support.h): every shipped
// schema stays inside it, and a schema outside it is refused rather than
// half-applied.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/schema_pattern.h"
#include "core/schema_support.h"
#include "core/schema_validation.h"

namespace gridfree {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

TEST(SchemaSupport, EveryShippedSchemaIsInsideTheSubset) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(GRIDFREE_SOURCE_DIR) / "schemas")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    const json schema = json::parse(in);
    const auto parts = unsupported_schema_parts(schema);
    EXPECT_TRUE(parts.empty()) << entry.path().filename() << ": " << (parts.empty() ? "" : parts.front());
    // And the embedded copy loads (the same check runs at load time).
    EXPECT_NO_THROW(load_embedded_schema(entry.path().filename().string()));
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(SchemaSupport, UnsupportedKeywordsAndPatternsAreRefusedWithTheirPointer) {
  auto parts = unsupported_schema_parts({{"properties", {{"a", {{"not", {{"type", "string"}}}}}}}});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0], "/properties/a/not: unsupported keyword");
  parts = unsupported_schema_parts({{"allOf", {{{"patternProperties", json::object()}}}}});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0], "/allOf/0/patternProperties: unsupported keyword");
  EXPECT_EQ(unsupported_schema_parts({{"pattern", "^(a|b)$"}}).size(), 1u);
  EXPECT_EQ(unsupported_schema_parts({{"type", "decimal"}}).size(), 1u);
  EXPECT_EQ(unsupported_schema_parts({{"exclusiveMinimum", true}}).size(), 1u);  // draft-04 form
  EXPECT_TRUE(unsupported_schema_parts({{"title", "t"}, {"items", {{{"const", 1}}}}, {"additionalItems", false}}).empty());
}

TEST(SchemaPattern, CompilesOnlyTheSubset) {
  std::string why;
  EXPECT_TRUE(SchemaPattern::compile("^[A-Za-z0-9][A-Za-z0-9._-]*$", &why));
  EXPECT_TRUE(SchemaPattern::compile("a\\.b+[^x]?", &why));
  for (const char* bad : {"(a)", "a|b", "a{2}", "[a-", "\\d", "a^b"})
    EXPECT_FALSE(SchemaPattern::compile(bad, &why)) << bad;
  const auto p = SchemaPattern::compile("^[^x]a*$", &why);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->matches("yaaa"));
  EXPECT_FALSE(p->matches("xaaa"));
  EXPECT_FALSE(p->matches(""));
}

}  // namespace
}  // namespace gridfree
