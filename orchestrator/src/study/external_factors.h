// SPDX-License-Identifier: GPL-3.0-or-later
// Factors of an external study (docs/INTERFACE.md §3 "External cases",
// docs/EXTERNAL.md "Factors, designs and ensembles"): the study's own
// factor names, each a placeholder @@name@@ of the template, with levels
// that are substituted as text into the rendered files.
//
// Rules, each broken rule a problem at its JSON pointer:
//   /factors/<name>        a name of letters, digits and '_' (not starting
//                          with a digit); not a grid or derived variable,
//                          not `cores`; an array of at least one level; the
//                          placeholder @@name@@ in a rendered file of every case
//   /factors/<name>/<i>    a string or a number, listed once (a number's
//                          text is JSON's: 3 → "3", 0.5 → "0.5", 1e-5 → "1e-05")
//   /design/one_at_a_time/<name>  `case` or a factor, its value one of its levels
#pragma once

#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

struct Study;

// A level's text: a string verbatim, a number as JSON writes it.
std::string level_text(const nlohmann::json& level);

// Reads doc["factors"] of an external study into study.factors.external.
void parse_external_factors(const nlohmann::json& doc, Study& study, ProblemList& problems);

// Reads doc["design"] of an external study: its one_at_a_time baseline
// (case and levels; a field left out is the first case or the first level).
void parse_external_design(const nlohmann::json& doc, Study& study, ProblemList& problems);

// The factor names of the study, as placeholders the render check accepts.
std::set<std::string> external_factor_names(const Study& study);

// After the cases are read: each factor is a placeholder of a rendered
// file of every case, and no grid or derived variable of any case.
void check_external_factor_placeholders(const Study& study, ProblemList& problems);

}  // namespace gridfree
