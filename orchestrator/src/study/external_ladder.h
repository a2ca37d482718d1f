// SPDX-License-Identifier: GPL-3.0-or-later
// The adaptive ladder of an external case (docs/EXTERNAL.md "Adaptive
// series"): the study gives its one grid variable's coarsest and finest
// values (study/adaptive_grids.h, AdaptiveVariable); the ladder is in the
// case's h, as gridfree's own ladder is in Δ*:
//
//   h_k = h(coarsest) / ratio^k,  k = 0 .. K,  K the last with h_k ≥ h(finest)
//
// and each rung's variable is the value v with h(v) = h_k, found by
// bisection between coarsest and finest, then rounded to its type (an
// integer to the nearer of its two neighbours in h, a real to 4
// significant digits); the derived variables, h and cells of the rung are
// then computed from it by the case's expressions (external_grid).
//
// Requirements, refused with the JSON path: h must never increase from
// coarsest to finest (sampled at every integer of the range, or at 2001
// points of a real range; flat steps, as rounded cell counts give, are
// allowed) and be lower at finest (at /cases/NAME/external/h); two
// neighbouring rungs must not round to the same value (at /grids/ratio);
// the ladder must hold kMinLadder rungs (at /grids/variables/NAME/finest).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/adaptive_grids.h"
#include "study/external_case.h"

namespace gridfree {

struct ExternalLadder {
  std::vector<double> h_nominal;  // h_k of the ladder
  GridVariables variables;        // the grid variable's (rounded) value on each rung
};

// The ladder of case `c` (named `case_name` in the study). On a problem,
// adds it to `problems` and returns an empty ladder.
ExternalLadder external_ladder(const ExternalCase& c, const AdaptiveVariable& v, double ratio,
                               const std::string& case_name, ProblemList& problems);

// The expressions of an external case (variables, h, cells) and its declared
// cost figures, from its study JSON (`extends` resolved): what a ladder and
// a cost estimate need, without reading the template or running anything.
ExternalCase external_expressions(const nlohmann::json& ext);

}  // namespace gridfree
