// SPDX-License-Identifier: GPL-3.0-or-later
// A grid-convergence series: pairs (h_i, f_i) of a representative cell size
// h (Δ* in this project) and the quantity of interest f on that grid.
//
// make_series validates the user's numbers and sorts them by h ascending
// (finest grid first), the order every procedure in extrap/ works in
// (PHYSICS.md §8: "Sort by h"). Weights of the least-squares fits:
//
//     W_i = 1/h_i,   w_i = W_i / Σ_j W_j            (PHYSICS.md §8, EH14 eq. 11)
//
// or uniform w_i = 1/n_g (EH14's unweighted fits), so Σ w_i = 1 either way.
#pragma once

#include <cstddef>
#include <vector>

namespace gridfree {

struct Series {
  std::vector<double> h;  // ascending, strictly increasing, all > 0
  std::vector<double> f;  // f[i] belongs to h[i]
  std::size_t size() const { return h.size(); }
};

enum class Weighting { kInverseH, kUniform };

// Validates and sorts. Problems (each with a JSON pointer into {"h": [...],
// "f": [...]}): lengths differ, fewer than 2 values, a value that is NaN or
// infinite, h <= 0, two h equal (relative difference below 1e-12).
// Throws InputError listing every problem found.
Series make_series(const std::vector<double>& h, const std::vector<double>& f);

// Normalised weights (Σ w = 1) for sorted or unsorted h.
std::vector<double> fit_weights(const std::vector<double>& h, Weighting weighting);

// Data range parameter R_f = (max f − min f) / (n − 1)  (PHYSICS.md §8; EH14 eq. 19).
double data_range(const std::vector<double>& f);

// True when the f values do not vary (max − min ≤ 1e-12·max|f|, or all zero):
// no fit is possible and none is needed (the error estimate is zero).
bool is_constant(const std::vector<double>& f);

}  // namespace gridfree
