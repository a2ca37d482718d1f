// SPDX-License-Identifier: GPL-3.0-or-later
// Migration steps kept in their own files (schema.cpp runs them in order).
#pragma once

#include "store/sqlite.h"

namespace gridfree {

// Step 5 (schema_transfer.cpp): the series table rebuilt with its transfer
// columns in the UNIQUE key. Needs foreign keys off (migrate() does that).
void migrate_series_transfer(Database& db);

// Step 6 (schema_alignment.cpp): alignment variants of a series' grids,
// study_jobs.alignment_only, v_alignment; v_results without the variants.
void migrate_alignment(Database& db);

// Step 11 (schema_job_hashes.cpp): job hashes of the normalised document
// (defaults filled in); jobs that become equal merged into one.
void migrate_job_hashes(Database& db);

// Step 12 (schema_quantity.cpp): series.quantity (an external case's
// quantity, '' for dp*) in the series' UNIQUE key; the table rebuilt.
void migrate_series_quantity(Database& db);

// Step 13 (schema_levels.cpp): series.levels (an external series' factor
// levels as canonical JSON, '{}' without) in the UNIQUE key; convection,
// fwhm_dp, drag and deposition NULL for external series; v_results,
// v_series and v_ensemble_budget made again with quantity and levels.
void migrate_series_levels(Database& db);

}  // namespace gridfree
