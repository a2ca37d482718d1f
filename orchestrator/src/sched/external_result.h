// SPDX-License-Identifier: GPL-3.0-or-later
// Results of external jobs (docs/EXTERNAL.md): what the scheduler adds to
// them before they are stored, and how a finished one is logged.
#pragma once

#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "store/store.h"
#include "study/external_plan.h"

namespace gridfree {

bool is_external_job(const nlohmann::json& spec);

// For an external job (spec with case.external), writes the collect section
// the result was read with into the stored result document as
// "collected_with", so a later change of the study's collect section is
// seen (re-collection, sched/recollect.h). Other jobs: unchanged.
void note_collect_spec(const nlohmann::json& spec, ResultRow& row);

// An external job's default timeout: kJobTimeoutMargin × its estimated CPU
// seconds (declared per cell × cells, else from the case's history), at
// least kMinJobTimeoutS (sched/job_timeout.h); none (0) when unknown:
// gridfree cannot guess another code's run time (give --timeout or the
// study's timeout_s).
double external_job_timeout_s(const ExternalJobCost& cost);

// "converged dp* = 1.234 (2.0 s)", or for an external result
// "converged kinetic_energy = 0.0672, ux_probe = 0.11 (2.0 s)".
std::string converged_message(const ResultRow& row);

}  // namespace gridfree
