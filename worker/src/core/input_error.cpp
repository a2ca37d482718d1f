// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/input_error.h"

namespace gridfree {

std::string format_problems(const std::vector<Problem>& problems) {
  std::string out;
  for (const auto& p : problems) {
    if (!out.empty()) out += '\n';
    out += p.where.empty() ? p.reason : p.where + ": " + p.reason;
  }
  return out;
}

InputError::InputError(std::vector<Problem> problems)
    : std::runtime_error(format_problems(problems)), problems_(std::move(problems)) {}

InputError::InputError(std::string where, std::string reason)
    : InputError(std::vector<Problem>{{std::move(where), std::move(reason)}}) {}

}  // namespace gridfree
