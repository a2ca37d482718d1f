// SPDX-License-Identifier: GPL-3.0-or-later
// Validation and sorting of a grid-convergence series; fit weights; data range.
#include "extrap/series.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/input_error.h"

namespace gridfree {
namespace {

// Relative tolerance below which two cell sizes count as the same grid.
constexpr double kDuplicateTolerance = 1e-12;

std::string pointer(const char* array, std::size_t i) {
  return std::string("/") + array + "/" + std::to_string(i);
}

}  // namespace

Series make_series(const std::vector<double>& h, const std::vector<double>& f) {
  ProblemList problems;
  if (h.size() != f.size())
    problems.add("/f", "has " + std::to_string(f.size()) + " values but /h has " +
                           std::to_string(h.size()) + "; every grid needs one h and one f");
  if (h.size() < 2)
    problems.add("/h", "needs at least 2 grids, got " + std::to_string(h.size()));
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!std::isfinite(h[i]))
      problems.add(pointer("h", i), "must be a finite number");
    else if (h[i] <= 0)
      problems.add(pointer("h", i), "cell size must be positive, got " + std::to_string(h[i]));
  }
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!std::isfinite(f[i])) problems.add(pointer("f", i), "must be a finite number");
  problems.throw_if_any();

  std::vector<std::size_t> order(h.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&h](std::size_t a, std::size_t b) { return h[a] < h[b]; });
  for (std::size_t k = 1; k < order.size(); ++k) {
    const double lo = h[order[k - 1]], hi = h[order[k]];
    if (hi - lo <= kDuplicateTolerance * hi)
      problems.add(pointer("h", order[k]),
                   "duplicate cell size (same as /h/" + std::to_string(order[k - 1]) +
                       "); each grid must appear once");
  }
  problems.throw_if_any();

  Series s;
  s.h.reserve(h.size());
  s.f.reserve(f.size());
  for (std::size_t i : order) {
    s.h.push_back(h[i]);
    s.f.push_back(f[i]);
  }
  return s;
}

std::vector<double> fit_weights(const std::vector<double>& h, Weighting weighting) {
  std::vector<double> w(h.size(), 1.0);
  if (weighting == Weighting::kInverseH)
    for (std::size_t i = 0; i < h.size(); ++i) w[i] = 1.0 / h[i];
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (double& wi : w) wi /= total;
  return w;
}

double data_range(const std::vector<double>& f) {
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  return (*hi - *lo) / static_cast<double>(f.size() - 1);
}

bool is_constant(const std::vector<double>& f) {
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  const double scale = std::max(std::fabs(*lo), std::fabs(*hi));
  return *hi - *lo <= 1e-12 * scale;
}

}  // namespace gridfree
