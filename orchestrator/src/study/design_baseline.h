// SPDX-License-Identifier: GPL-3.0-or-later
// A study's "design" (docs/INTERFACE.md §3): "factorial" (or absent), or
// {"one_at_a_time": {baseline}}. Both kinds of case read it here and check
// the baseline's fields against their own factors.
#pragma once

#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace gridfree {

// The one_at_a_time baseline object of doc["design"]; nullptr for a
// factorial design, and for a malformed one after adding the problem at
// /design.
const nlohmann::json* one_at_a_time_baseline(const nlohmann::json& doc, ProblemList& problems);

}  // namespace gridfree
