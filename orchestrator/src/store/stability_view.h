// SPDX-License-Identifier: GPL-3.0-or-later
// The view v_stability (docs/DATABASE.md "v_stability"): one row per grid of
// a series (alignment variants left out) with its outcome word, classified
// as the report's stability map does (report/stability_map.h):
// converged | stalled | iteration_cap | diverged | invalid | timed_out |
// failed | pending | cancelled, with the outer iterations and the reason.
//
// Not a numbered schema step: migrate() creates it with CREATE VIEW IF NOT
// EXISTS after the steps (any schema version ≥ 10 has it; a database
// written before it gains it at its next open). It reads only base tables,
// so a later step that redefines v_results leaves it intact.
#pragma once

#include "store/sqlite.h"

namespace gridfree {

void ensure_stability_view(Database& db);

}  // namespace gridfree
