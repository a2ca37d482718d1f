// SPDX-License-Identifier: GPL-3.0-or-later
// Case inheritance in a study: a case may name another case of the same
// study in "extends" and give only the fields it changes.
//
//   resolved(case) = merge_patch(resolved(base), case without "extends")
//
// merge_patch is RFC 7386 JSON Merge Patch: objects merge key by key
// (recursively), any other value (number, string, array) replaces the
// base's, and null removes the key. Chains are allowed; an unknown base, a
// non-string "extends" or a cycle is a problem at /cases/<name>/extends.
// A case's "name" is never inherited.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// The study document with every case's "extends" resolved (and removed).
// A case whose chain cannot be resolved is left out of the result (so it
// draws no further problems), and a problem is added at its "extends".
nlohmann::json resolve_case_extends(const nlohmann::json& study_doc, ProblemList& problems);

// One case of the study with its "extends" chain resolved (the work of its
// chain only); null when the case is missing or its chain is broken.
nlohmann::json resolved_case(const nlohmann::json& study_doc, const std::string& name);

}  // namespace gridfree
