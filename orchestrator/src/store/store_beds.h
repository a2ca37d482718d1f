// SPDX-License-Identifier: GPL-3.0-or-later
// The bed summary (the result's "bed", docs/INTERFACE.md §2) of each case of
// a study, read for the report's "About this case" (report/bed_about.h).
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "store/sqlite.h"

namespace gridfree {

// Case name → the "bed" object of one of its results (every job of a case
// solves the same particles, so any one serves: the lowest job id). Cases
// without such a result (a continuum bed, no finished job, results written
// before the field existed) are absent. One query, whatever the number of
// series.
std::map<std::string, nlohmann::json> case_beds(Database& db, long long study_id);

}  // namespace gridfree
