// SPDX-License-Identifier: GPL-3.0-or-later
// Geometric-series iterative-error estimate (iterative_error.h).
#include "flow/iterative_error.h"

#include <cmath>

namespace gridfree {

std::optional<double> geometric_iterative_error(const std::deque<double>& history, int window) {
  const std::size_t n = history.size();
  const std::size_t w = std::size_t(window);
  if (window < 1 || n < 2 * w + 1) return std::nullopt;
  const double q = history[n - 1];
  const double recent = std::abs(q - history[n - 1 - w]);
  const double before = std::abs(history[n - 1 - w] - history[n - 1 - 2 * w]);
  if (recent == 0.0) return 0.0;
  if (!(before > recent) || q == 0.0) return std::nullopt;
  const double ratio = recent / before;
  return recent * ratio / (1.0 - ratio) / std::abs(q);
}

}  // namespace gridfree
