// SPDX-License-Identifier: GPL-3.0-or-later
// Every grid of a study, per case: the Δ* requested, the Δ* actually
// obtained after rounding the cells (Δ* = (V/N)^(1/3)/d), and the cells; and
// warnings about neighbouring grids too close to tell apart.
//
// Two grids whose actual Δ* differ by a ratio below kMinNeighbourRatio (1.1)
// add almost no information on the trend with h: their difference is
// dominated by the grid-to-grid scatter of the particle transfer
// (docs/PHYSICS.md §3), so they are flagged (a warning, not an error).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study.h"

namespace gridfree {

inline constexpr double kMinNeighbourRatio = 1.1;

struct GridRow {
  std::string case_name;
  std::size_t index = 0;                 // position in the study's grid list
  std::string pointer;                   // grid_pointer(study, index)
  std::optional<double> requested;       // Δ* asked for (none for explicit cells)
  double actual = 0;                     // Δ* of the cells
  std::array<int, 3> cells{};
  std::uint64_t cell_count = 0;
  std::string h_meaning;                 // an external case's: its declared h ("h = 1 / N"); `actual` is h
  // The study's cores rule on this grid before the pool's cap
  // (study/job_cores.h); nullopt without a rule.
  std::optional<int> cores;
  std::string cores_rule;                // the rule, for the table's note
};

// Where grid `i` of `study` is written: /grids/delta_star/i or
// /grids/cells/i; for adaptive grids, whose ladder the file does not list,
// "/grids ladder rung <i+1>" (docs/INTERFACE.md "Grids as a target").
std::string grid_pointer(const Study& study, std::size_t i);

// Per case in file order, grids in the study's order.
std::vector<GridRow> grid_listing(const Study& study);

// "case C: /grids/delta_star/2 (Δ* 1.667) and /grids/delta_star/3 (Δ* 1.6):
// ratio 1.04 < 1.1 ..." for each pair of neighbours (sorted by actual Δ*)
// closer than `min_ratio`.
std::vector<std::string> neighbour_warnings(const std::vector<GridRow>& rows,
                                            double min_ratio = kMinNeighbourRatio);

// An external study's table lists h and cells (no Δ*, no nx x ny x nz),
// with each case's declared meaning of h below it. A study with a cores
// rule gets a cores column and the rule below the table.
std::string grid_listing_table(const std::vector<GridRow>& rows);
nlohmann::json grid_listing_json(const std::vector<GridRow>& rows);

}  // namespace gridfree
