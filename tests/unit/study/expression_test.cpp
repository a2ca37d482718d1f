// SPDX-License-Identifier: GPL-3.0-or-later
// The study expression evaluator (study/expression.h): precedence, the
// functions, and errors that name the expression, the position and what
// was expected.
#include <gtest/gtest.h>

#include <cmath>

#include "study/expression.h"

namespace gridfree {
namespace {

double eval(const char* text, std::map<std::string, double> vars = {}) { return evaluate_expression(text, vars); }

std::string error_of(const char* text, std::map<std::string, double> vars = {}) {
  try {
    evaluate_expression(text, vars);
  } catch (const ExpressionError& e) {
    return e.what();
  }
  return "";
}

TEST(StudyExpression, NumbersAndPrecedence) {
  EXPECT_EQ(eval("1 + 2 * 3"), 7);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9);
  EXPECT_EQ(eval("2 ^ 3 ^ 2"), 512);  // right-associative
  EXPECT_EQ(eval("-2 ^ 2"), -4);      // power above unary minus
  EXPECT_EQ(eval("2 ^ -1"), 0.5);
  EXPECT_EQ(eval("8 / 4 / 2"), 1);    // left-associative
  EXPECT_EQ(eval("1e-3 * 2.5E2"), 0.25);
  EXPECT_EQ(eval(".5 + 1."), 1.5);
}

TEST(StudyExpression, VariablesAndFunctions) {
  const std::map<std::string, double> v{{"N", 40}, {"L_x", 0.1}};
  EXPECT_DOUBLE_EQ(eval("L_x / N", v), 0.0025);
  EXPECT_EQ(eval("sqrt(N * 10)", v), 20);
  EXPECT_EQ(eval("pow(N, 2)", v), 1600);
  EXPECT_EQ(eval("min(N, 3, 7)", v), 3);
  EXPECT_EQ(eval("max(N, 3)", v), 40);
  EXPECT_EQ(eval("floor(2.7) + ceil(2.2) + round(2.5)", v), 8);
  EXPECT_DOUBLE_EQ(eval("log(exp(2))", v), 2);
}

TEST(StudyExpression, IeeeArithmeticIsLeftToTheCaller) {
  EXPECT_TRUE(std::isinf(eval("1 / 0")));
  EXPECT_TRUE(std::isnan(eval("log(-1)")));
}

TEST(StudyExpression, ErrorsNameExpressionPositionAndExpectation) {
  EXPECT_EQ(error_of("1 +"), "expression '1 +': at position 4: expected a number, a name or '(', found the end");
  EXPECT_EQ(error_of("2 * (N", {{"N", 1}}), "expression '2 * (N': at position 7: expected ')', found the end");
  EXPECT_EQ(error_of("1 $ 2"), "expression '1 $ 2': at position 3: expected an operator (+ - * / ^) or the end, found '$'");
  EXPECT_EQ(error_of("0.1 / M", {{"N", 1}, {"dt", 2}}),
            "expression '0.1 / M': at position 7: unknown name 'M' (defined: N, dt)");
  EXPECT_EQ(error_of("system(1)"),
            "expression 'system(1)': at position 1: unknown function 'system' (known: sqrt, pow, min, max, floor, "
            "ceil, round, log, exp)");
  EXPECT_EQ(error_of("pow(2)"), "expression 'pow(2)': at position 1: pow takes 2 argument(s), not 1");
  EXPECT_EQ(error_of("1.2.3"), "expression '1.2.3': at position 1: expected a number, found '1'");
  EXPECT_EQ(error_of(""), "expression '': at position 1: expected a number, a name or '(', found the end");
  try {
    evaluate_expression("1 + ", {});
    FAIL();
  } catch (const ExpressionError& e) {
    EXPECT_EQ(e.position(), 5u);
  }
}

TEST(StudyExpression, NamesRead) {
  EXPECT_EQ(expression_names("0.1 / N + sqrt(M * N)"), (std::set<std::string>{"M", "N"}));
  EXPECT_THROW(expression_names("N +"), ExpressionError);
}

}  // namespace
}  // namespace gridfree
