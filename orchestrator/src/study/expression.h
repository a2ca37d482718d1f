// SPDX-License-Identifier: GPL-3.0-or-later
// A small arithmetic expression language for external cases' derived grid
// variables (docs/INTERFACE.md "External cases"): numbers, names of
// variables, + - * / ^ (power, right-associative, above unary minus:
// -2^2 = -4), parentheses, and the functions sqrt, pow, min, max, floor,
// ceil, round, log (natural), exp. Nothing else: no assignment, no
// strings, no loops, so a study file cannot run anything through it.
//
// Pure: evaluate_expression reads only its arguments. A malformed
// expression or an unknown name throws ExpressionError naming the
// expression, the 1-based character position and what was expected there.
// Arithmetic follows IEEE doubles: 1/0 is inf, log(-1) NaN; the caller
// decides whether a non-finite value is acceptable.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gridfree {

class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(const std::string& message, std::size_t position)
      : std::runtime_error(message), position_(position) {}
  std::size_t position() const { return position_; }  // 1-based; 0 when not tied to one
 private:
  std::size_t position_;
};

// The value of `text` with the given variables.
double evaluate_expression(std::string_view text, const std::map<std::string, double>& variables);

// The variable names `text` reads (function names excluded). Throws
// ExpressionError when the text does not parse.
std::set<std::string> expression_names(std::string_view text);

}  // namespace gridfree
