// SPDX-License-Identifier: GPL-3.0-or-later
// What every iterative solve returns (Basilisk's mgstats, in spirit).
#pragma once

namespace gridfree {

struct LinearSolveStats {
  int iterations = 0;
  double initial_residual = 0;  // ||r0|| / ||b||
  double final_residual = 0;    // ||r|| / ||b||
  bool converged = false;
};

}  // namespace gridfree
