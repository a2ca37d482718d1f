// SPDX-License-Identifier: GPL-3.0-or-later
// The cost model's history (study/cost_model.h, rule (a)): the finished,
// converged jobs of a database with their cell counts, measured CPU
// seconds and peak memory, grouped by similarity key. Jobs that stopped at max_iterations,
// diverged or failed are left out: their time says nothing about a job
// that converges (docs/ORCHESTRATOR.md "Cost model"). The database is only
// read; a missing file gives an empty history.
#pragma once

#include <filesystem>

#include "study/cost_model.h"

namespace gridfree {

CostHistory read_cost_history(const std::filesystem::path& db_file);
// From an open database; `external_only`: external jobs' only (the
// scheduler's estimates of external codes, study/external_plan.h).
class Database;
CostHistory read_cost_history(Database& db, bool external_only);

}  // namespace gridfree
