// SPDX-License-Identifier: GPL-3.0-or-later
// The normalised job document: what a job's identity (job/job_hash.h) is
// computed from. Every optional field left out is written with its default
// (docs/INTERFACE.md §2, the "default" of schemas/job.schema.json), so a job
// that omits `gravity_cm_s2`, `probes`, `tolerances` ... and the same job
// with the defaults written out are one job. numerics.deposition is written
// expanded (presets and defaults, job/deposition_parse.cpp).
//
// Pure: the document is not validated; parts that are not objects where an
// object is expected are left as they are (an invalid job is refused by
// parse_job before it is hashed or run).
#pragma once

#include <nlohmann/json.hpp>

namespace gridfree {

nlohmann::json normalised_job(const nlohmann::json& job_doc);

}  // namespace gridfree
