// SPDX-License-Identifier: GPL-3.0-or-later
// What an external job's result gets before it is stored (docs/EXTERNAL.md
// "The study"): the collect section it was read with, so a later change of
// the study's collect section is seen (re-collection, sched/recollect.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace gridfree {

// Writes the job document's case.external.collect into the result document
// `result_json` as "collected_with"; unchanged when the job has none or the
// result is not a JSON object.
void record_collect_spec(const nlohmann::json& spec, std::string& result_json);

}  // namespace gridfree
