// SPDX-License-Identifier: GPL-3.0-or-later
// Store side of the study's alignment check (schema step 6,
// schema_alignment.cpp) and the series' transfer columns (step 5).
#pragma once

#include <optional>
#include <vector>

#include "store/sqlite.h"
#include "study/study.h"

namespace gridfree {

// Writes the series' transfer columns (inside submit's transaction).
void store_series_transfer(Database& db, const std::vector<long long>& series_ids, const ExpandedStudy& expanded);

// Inserts the variant jobs (INSERT OR IGNORE by hash), links them to the
// study with alignment_only = 1 (a job that is already one of the series'
// own grids stays a series job), and records every (series, grid, job) of
// the check, the grid's own job included with offsets 0, 0, 0. Returns how
// many jobs were new. Inside submit's transaction.
std::size_t store_alignment_jobs(Database& db, long long study_id, const std::vector<long long>& series_ids,
                                 const ExpandedStudy& expanded);

// One row of v_alignment (docs/DATABASE.md).
struct AlignmentRow {
  long long series_id = 0;
  int grid_index = 0;
  std::array<int, 3> cells{};
  double delta_star = 0;
  int variants = 0, converged = 0;
  std::optional<double> dp_min, dp_max, dp_mean, spread, f, u;
};

// dp* of every job of one checked grid (the grid first, then the variants
// by offset); nullopt where the job has not converged (yet).
struct AlignmentValues {
  long long series_id = 0;
  int grid_index = 0;
  double delta_star = 0;
  std::array<int, 3> cells{};
  std::vector<std::optional<double>> dp_star;
};
std::vector<AlignmentValues> alignment_values(Database& db, long long study_id);

// The study's alignment rows, by series position and grid.
std::vector<AlignmentRow> alignment_rows(Database& db, long long study_id);

}  // namespace gridfree
