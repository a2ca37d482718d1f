// SPDX-License-Identifier: GPL-3.0-or-later
// Limits on JSON text (core/json_limits.h): depth, number range and size are
// refused at their line:column before parsing; brackets and digits inside
// strings do not count; messages stay printable and short.
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "core/json_limits.h"

namespace gridfree {
namespace {

// The single problem's "where: reason", or "" when the text parses.
std::string refusal(const std::string& text) {
  try {
    parse_json_text(text, "doc.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.problems().size(), 1u);
    return e.problems().front().where + ": " + e.problems().front().reason;
  }
  return "";
}

TEST(JsonLimits, DepthUpToTheLimitParsesBeyondIsRefusedWhereItHappens) {
  const std::size_t n = kMaxJsonDepth;
  EXPECT_EQ(refusal(std::string(n, '[') + std::string(n, ']')), "");
  const std::string deep = "{\"a\":\n  " + std::string(n, '[') + std::string(n, ']') + "}";
  // The outer object is level 1, so the array opening level 65 is the 64th '['.
  EXPECT_EQ(refusal(deep).rfind("doc.json:2:" + std::to_string(2 + n) + ": nested deeper than 64", 0), 0u)
      << refusal(deep);
  EXPECT_NE(refusal(std::string(100000, '[')).find("nested deeper"), std::string::npos);
}

TEST(JsonLimits, BracketsAndDigitsInsideStringsDoNotCount) {
  EXPECT_EQ(refusal("{\"k\": \"" + std::string(100, '[') + " 1e999 \\\" [[\"}"), "");
}

TEST(JsonLimits, NumbersBeyondADoubleAreRefused) {
  EXPECT_EQ(refusal("[1.7976931348623157e308, -1e308, 5e-324]"), "");
  EXPECT_NE(refusal("[1, 1e309]").find("doc.json:1:5: number 1e309 is out of the range"), std::string::npos)
      << refusal("[1, 1e309]");
  EXPECT_NE(refusal("{\"x\": -1e400}").find("-1e400"), std::string::npos);
  const std::string digits(400, '9');
  const std::string r = refusal("[" + digits + "]");
  EXPECT_NE(r.find("(400 characters)"), std::string::npos) << r;
  EXPECT_LT(r.size(), 160u);
  // Underflow reads as 0; the fields' ranges refuse it where 0 is wrong.
  EXPECT_EQ(parse_json_text("[1e-400]", "doc.json")[0].get<double>(), 0.0);
}

TEST(JsonLimits, SyntaxErrorsNameLineAndColumnInPrintableWords) {
  const std::string r = refusal("{\n  \"name\": \"a\xff\"\n}");
  EXPECT_EQ(r.rfind("doc.json:2:", 0), 0u) << r;
  EXPECT_EQ(r.find('\xff'), std::string::npos) << "raw invalid byte in the message";
  const std::string long_token = "[" + std::string(5000, 'x') + "]";
  EXPECT_LT(refusal(long_token).size(), 260u);
}

TEST(JsonLimits, OversizedTextIsRefusedBeforeParsing) {
  const std::string big(kMaxJsonBytes + 1, ' ');
  EXPECT_NE(refusal(big).find("larger than 64 MiB"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
