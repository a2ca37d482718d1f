// SPDX-License-Identifier: GPL-3.0-or-later
// `gridfree status STUDY --json`'s "stability" (docs/ORCHESTRATOR.md): the
// outcome of every grid of every series, read from the view v_stability
// (store/stability_view.h), the same words as the report's stability map:
//   {"counts": {"converged": 12, "invalid": 3, ...},
//    "series": [{"series_id", "case", "convection", "fwhm_dp", "drag", "deposition",
//                "grids": [{"delta_star", "delta_star_nominal", "outcome", "iterations", "reason"}]}]}
// Grids coarsest first; reason only for grids that did not converge.
#pragma once

#include <nlohmann/json.hpp>

#include "store/store.h"

namespace gridfree {

nlohmann::json stability_status(Store& store, long long study_id);

}  // namespace gridfree
