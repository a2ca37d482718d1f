// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/command_suggestion.h"

#include <algorithm>

namespace gridfree {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string nearest_name(std::string_view word, const std::vector<std::string>& names) {
  if (word.size() > 64) return "";
  std::string best;
  std::size_t best_distance = 3;
  for (const auto& name : names) {
    const std::size_t dist = edit_distance(word, name);
    if (dist < best_distance && dist < name.size()) {
      best = name;
      best_distance = dist;
    }
  }
  return best;
}

std::string unknown_command_message(std::string_view word, const std::vector<std::string>& names) {
  const std::string shown(word.substr(0, 64));
  std::string text = "unknown command '" + shown + "'";
  const std::string near = nearest_name(word, names);
  if (!near.empty()) return text + "; did you mean '" + near + "'?";
  text += "; commands:";
  for (std::size_t i = 0; i < names.size(); ++i) text += (i == 0 ? " " : ", ") + names[i];
  return text;
}

}  // namespace gridfree
