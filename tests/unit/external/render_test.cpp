// SPDX-License-Identifier: GPL-3.0-or-later
// @@name@@ rendering: numbers as written, undefined names refused with file
// and line, anything that is not a placeholder left alone (OpenFOAM's own
// braces, $variables and #include lines, a lone @@).
#include <gtest/gtest.h>

#include "external/render.h"

namespace gridfree {
namespace {

TEST(ExternalRender, NumbersAsWritten) {
  EXPECT_EQ(render_number(40), "40");  // integers as integers, not 40.0
  EXPECT_EQ(render_number(-3), "-3");
  EXPECT_EQ(render_number(0.0025), "0.0025");  // shortest round trip
  EXPECT_EQ(render_number(0.1 / 3), "0.03333333333333333");
  EXPECT_EQ(render_number(1e-5), "1e-05");
  EXPECT_EQ(render_number(1e20), "1e+20");  // beyond exact integers: not a 21-digit integer
}

TEST(ExternalRender, SubstitutesEveryPlaceholderAndNothingElse) {
  const RenderVariables vars = {{"N", 16}, {"dt", 0.00625}, {"end_time", 1}};
  const std::string text =
      "hex (0 1 2 3 4 5 6 7) (@@N@@ @@N@@ 1) simpleGrading (1 1 1);\n"
      "deltaT @@dt@@; endTime @@end_time@@;\n"
      "p { $p; relTol 0; } #include \"x\" mail@@host @@ @@@@ @@1x@@\n";
  EXPECT_EQ(render_placeholders(text, vars, "f"),
            "hex (0 1 2 3 4 5 6 7) (16 16 1) simpleGrading (1 1 1);\n"
            "deltaT 0.00625; endTime 1;\n"
            "p { $p; relTol 0; } #include \"x\" mail@@host @@ @@@@ @@1x@@\n");
}

TEST(ExternalRender, UndefinedPlaceholderNamesFileLineAndName) {
  const RenderVariables vars = {{"N", 16}};
  try {
    (void)render_placeholders("a @@N@@\nb\nc @@Nx@@ d\n", vars, "system/blockMeshDict");
    FAIL() << "an undefined placeholder was rendered";
  } catch (const UndefinedPlaceholder& e) {
    EXPECT_EQ(e.file, "system/blockMeshDict");
    EXPECT_EQ(e.line, 3);
    EXPECT_EQ(e.name, "Nx");
    EXPECT_STREQ(e.what(), "system/blockMeshDict:3: @@Nx@@ is not a variable");
  }
}

TEST(ExternalRender, PlaceholderNames) {
  EXPECT_EQ(placeholder_names("@@a@@ x @@b_2@@@@a@@ @@ @@3@@"), (std::vector<std::string>{"a", "b_2", "a"}));
}

}  // namespace
}  // namespace gridfree
