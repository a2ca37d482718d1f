// SPDX-License-Identifier: GPL-3.0-or-later
// Warnings about a series' grids before anything is solved (`gridfree
// validate` and `plan`), from the verdict rules of docs/EXTRAPOLATION.md:
//
//   all Δ* > kAsymptoticDeltaStar  every grid is coarser than the range where
//                                  the bursting-bubble series were measured to
//                                  behave asymptotically (docs/EXTRAPOLATION.md)
//   n − 3 < VerdictRules::min_dof  too few grids for a `converged` verdict
#pragma once

#include <string>
#include <vector>

namespace gridfree {

inline constexpr double kAsymptoticDeltaStar = 2.0;

// h = the actual Δ* of one series' grids, any order. Empty when nothing to
// say. `particle_bed` false (an external case's declared h): the Δ* range
// measured on particle beds says nothing about it, only the count is judged.
std::vector<std::string> grid_design_warnings(const std::vector<double>& h, bool particle_bed = true);

}  // namespace gridfree
