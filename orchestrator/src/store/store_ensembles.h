// SPDX-License-Identifier: GPL-3.0-or-later
// The ensembles table (schema step 5, store/schema_ensembles.h): written at
// submit, read for the report.
#pragma once

#include "store/sqlite.h"
#include "study/study_ensembles.h"

namespace gridfree {

// One row per (ensemble, case) of a newly stored study.
void insert_ensembles(Database& db, long long study_id, const Ensembles& ensembles);

// A study's ensembles, cases in the order they were stored.
Ensembles study_ensembles(Database& db, long long study_id);

}  // namespace gridfree
