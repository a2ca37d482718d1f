// SPDX-License-Identifier: GPL-3.0-or-later
// The cores rule (study/job_cores.h).
#include "study/job_cores.h"

#include <algorithm>
#include <cmath>

#include "study/expression.h"

namespace gridfree {

std::string study_cores_expression(const nlohmann::json& definition) {
  if (!definition.is_object()) return "";
  const auto c = definition.find("cores");
  if (c == definition.end()) return "";
  if (c->is_string()) return c->get<std::string>();
  if (c->is_number_integer() || c->is_number_unsigned()) return std::to_string(c->get<long long>());
  return "";  // the schema refuses anything else
}

void check_cores_expression(const std::string& text, const std::string& where, ProblemList& problems) {
  try {
    for (const auto& n : expression_names(text))
      if (n != kCoresVariable)
        problems.add(where, "expression '" + text + "' reads '" + n + "'; the cores of a job are an expression of " +
                                std::string(kCoresVariable) + " only");
  } catch (const ExpressionError& e) {
    problems.add(where, e.what());
  }
}

double cores_value(const std::string& text, double cells) {
  return evaluate_expression(text, {{kCoresVariable, cells}});
}

std::optional<int> job_cores(const std::string& text, double cells, int cap) {
  const double v = cores_value(text, cells);
  if (!std::isfinite(v)) return std::nullopt;
  const double whole = std::max(1.0, std::floor(v));
  return static_cast<int>(std::min(whole, static_cast<double>(std::max(1, cap))));
}

}  // namespace gridfree
