// SPDX-License-Identifier: GPL-3.0-or-later
// Observed order of accuracy from errors on a sequence of refined grids
// (MFEM-style: halve the cell size, order = log(e_coarse/e_fine)/log(h_c/h_f)).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

struct OrderStudy {
  std::string equation;          // what was solved, e.g. "momentum_continuity_drag"
  std::string scheme;            // convection scheme or method
  std::string norm;              // error norm, e.g. "L1 velocity"
  double expected_order = 0;
  double observed_order = 0;     // from the two finest grids
  std::vector<int> grids;        // cells per direction of each grid, coarse to fine
  std::vector<double> h;         // cell sizes
  std::vector<double> errors;    // error on each grid
  std::vector<int> iterations;   // solver iterations on each grid (0: not iterative)
  std::string failure;           // non-empty when a grid could not be solved

  // Observed order within 0.2 of the expected one, or above it.
  bool passed() const;
};

// What one grid of a study gave: its error, or why it could not be solved.
struct GridOutcome {
  double error = 0;
  int iterations = 0;   // outer iterations of the solve (0: not iterative)
  std::string failure;  // non-empty: no error on this grid
};

// Fills s.grids, s.h (= 1/n), s.errors and s.observed_order from the
// outcomes of `grids` (same order). Stops at the first failed grid: its
// error is NaN and its reason becomes s.failure.
void finish_study(OrderStudy& s, const std::vector<int>& grids, const std::vector<GridOutcome>& outcomes);

// Order from the two finest grids: ln(e_{n−2}/e_{n−1}) / ln(h_{n−2}/h_{n−1}).
double observed_order(const std::vector<double>& h, const std::vector<double>& errors);

nlohmann::json to_json(const OrderStudy& s);

}  // namespace gridfree
