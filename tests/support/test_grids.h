// SPDX-License-Identifier: GPL-3.0-or-later
// Grids for the solver tests from their cell counts and box (without a
// case, unlike make_grid of job/case_grid.h).
#pragma once

#include <array>

#include "grid/grid.h"

namespace gridfree::test_support {

// n cells on a box of sides `length`, periodic along the axes `periodic` says.
inline Grid box_grid(std::array<int, 3> n, std::array<double, 3> length, std::array<bool, 3> periodic) {
  Grid g;
  g.n = n;
  g.length = length;
  g.periodic = periodic;
  return g;
}

// n cells on the unit cube.
inline Grid box_grid(std::array<int, 3> n, std::array<bool, 3> periodic) { return box_grid(n, {1, 1, 1}, periodic); }

}  // namespace gridfree::test_support
