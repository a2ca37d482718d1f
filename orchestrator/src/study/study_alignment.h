// SPDX-License-Identifier: GPL-3.0-or-later
// The alignment check as a study option (docs/INTERFACE.md §3,
// docs/TRANSFER.md "Alignment check"):
//
//   "alignment": {"delta_star": [3.3, 2], "ny_offsets": [1, 2, 3]}
//
// For each series and each listed grid ("delta_star" or "cells", values of
// the study's own grids; all grids when left out) the study also runs the
// grid with its cell counts changed by every combination of nx_offsets,
// ny_offsets and nz_offsets (a list left out is [0]; the all-zero
// combination is the grid itself). The variants are ordinary jobs; they do
// not enter the series' extrapolation. Default: off.
#pragma once

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/study.h"

namespace gridfree {

// Reads "alignment" (after the grids); problems carry their JSON path.
void parse_alignment(const nlohmann::json& doc, Study& study, ProblemList& problems);

// The offsets of the variants of one grid: every combination except 0,0,0.
std::vector<std::array<int, 3>> alignment_offsets(const AlignmentOption& option);

// The variant jobs of every series (appended to expanded.alignment), hashed;
// a variant equal to another already listed for the same series and grid is listed once.
void expand_alignment(const Study& study, ExpandedStudy& expanded);

}  // namespace gridfree
