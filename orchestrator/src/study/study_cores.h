// SPDX-License-Identifier: GPL-3.0-or-later
// Checks a study's "cores" rule (study/job_cores.h) against its grids.
#pragma once

#include "core/input_error.h"
#include "study/study.h"

namespace gridfree {

// /cores: the expression parses and reads only `cells`; an external case
// whose grids give no cells (no cells expression) cannot feed it; on every
// grid of every case its value is a finite number. Each problem at /cores.
void check_study_cores(const nlohmann::json& doc, const Study& s, ProblemList& problems);

}  // namespace gridfree
