// SPDX-License-Identifier: GPL-3.0-or-later
// Ensembles (docs/INTERFACE.md §3 "ensembles"): named groups of cases that
// are instances of one physical state — frozen snapshots of one transient
// run, say. The study runs every case as usual; the report and the database
// average each configuration (convection × fwhm_dp × drag × deposition) over
// the instances (docs/EXTRAPOLATION.md "Ensembles").
//
// Rules, each broken rule a problem at its JSON pointer:
//   /ensembles                 an object: ensemble name → array of case names
//   /ensembles/<name>          a name of letters, digits, '-', '_', '.' (it
//                              names report files); at least two cases
//   /ensembles/<name>/<i>      a case of /cases, listed once, and in no
//                              other ensemble
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

struct Study;

using Ensembles = std::map<std::string, std::vector<std::string>>;  // name → cases, as listed

// Reads doc["ensembles"] (absent = none) into study.ensembles; the study's
// cases must be parsed already.
void parse_ensembles(const nlohmann::json& doc, Study& study, ProblemList& problems);

// The ensemble a case belongs to, or "" when it is in none.
std::string ensemble_of(const Ensembles& ensembles, const std::string& case_name);

}  // namespace gridfree
