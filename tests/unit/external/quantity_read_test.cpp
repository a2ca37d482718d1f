// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a quantity's last two records: data rows (comments and blank lines
// skipped, OpenFOAM vectors split), regex matches, and the problem text
// when there is nothing to read.
#include <gtest/gtest.h>

#include "external/quantity_read.h"

namespace gridfree {
namespace {

TEST(ExternalQuantityRead, LastTwoDataRowsOfAColumn) {
  const std::string dat =
      "# Region        : all region0\n"
      "# Time          \tvolAverage(magSqr(U))\n"
      "0.99375         \t6.16451979e-02\n"
      "1               \t6.16451980e-02\n"
      "\n"
      "   # trailing comment\n";
  const auto r = read_column(dat, 1);
  ASSERT_TRUE(r.last);
  EXPECT_DOUBLE_EQ(*r.last, 6.16451980e-02);
  ASSERT_TRUE(r.previous);
  EXPECT_DOUBLE_EQ(*r.previous, 6.16451979e-02);
  EXPECT_TRUE(r.problem.empty());
  EXPECT_DOUBLE_EQ(*read_column(dat, 0).last, 1.0);
}

TEST(ExternalQuantityRead, VectorsCountAsColumns) {
  const auto r = read_column("# Time Fx\n0.5 (1.5 -2 3e-3) (4 5 6)\r\n", 3);
  ASSERT_TRUE(r.last);
  EXPECT_DOUBLE_EQ(*r.last, 3e-3);
  EXPECT_FALSE(r.previous);  // one row only
}

TEST(ExternalQuantityRead, NanAndInfAreNumbers) {
  EXPECT_TRUE(std::isnan(*read_column("1 nan\n", 1).last));
  EXPECT_TRUE(std::isinf(*read_column("1 -inf\n", 1).last));
}

TEST(ExternalQuantityRead, ProblemsSayWhat) {
  EXPECT_EQ(read_column("# only a header\n\n", 0).problem, "no data row (only comments or nothing)");
  EXPECT_EQ(read_column("1 2\n", 2).problem,
            "column 2 is not in the last row (2 columns, counted from 0: \"1 2\")");
  EXPECT_EQ(read_column("1 2\n1 garbage\n", 1).problem, "\"garbage\" in column 1 of the last row is not a number");
  EXPECT_FALSE(read_column("1 2\n1 garbage\n", 1).last);
}

TEST(ExternalQuantityRead, LastRegexMatches) {
  const std::regex re("Ux, Initial residual = ([-+0-9.eE]+)");
  const std::string log =
      "Time = 0.1\nsmoothSolver:  Solving for Ux, Initial residual = 0.5, Final residual = 1e-11\n"
      "Time = 0.2\nsmoothSolver:  Solving for Ux, Initial residual = 2.5e-06, Final residual = 1e-12\nEnd\n";
  const auto r = read_regex(log, re, "Ux...");
  ASSERT_TRUE(r.last);
  EXPECT_DOUBLE_EQ(*r.last, 2.5e-06);
  EXPECT_DOUBLE_EQ(*r.previous, 0.5);
  EXPECT_EQ(read_regex("nothing here\n", re, "Ux...").problem, "no line matches \"Ux...\"");
  EXPECT_EQ(read_regex("q = abc\n", std::regex("q = (\\w+)"), "q").problem,
            "the last match \"abc\" of \"q\" is not a number");
}

TEST(ExternalQuantityRead, FirstFailurePatternWithTheNextLine) {
  const std::string log =
      "Create time\n\n\n--> FOAM FATAL IO ERROR: \n\n  keyword deltaT is undefined\n\nFOAM FATAL again\n";
  const auto hit = find_pattern(log, {std::regex("FOAM FATAL"), std::regex("never")}, {"FOAM FATAL", "never"});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->pattern, "FOAM FATAL");
  EXPECT_EQ(hit->line, 4);
  EXPECT_EQ(hit->text, "--> FOAM FATAL IO ERROR: | keyword deltaT is undefined");
  EXPECT_FALSE(find_pattern("all good\n", {std::regex("FOAM FATAL")}, {"FOAM FATAL"}));
}

}  // namespace
}  // namespace gridfree
