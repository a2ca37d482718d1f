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

std::string error_lines(const InputError& e) {
  const std::string text = e.what();
  std::string out;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    if (end > at) out += "error: " + text.substr(at, end - at) + "\n";
    at = end + 1;
  }
  return out;
}

}  // namespace gridfree
