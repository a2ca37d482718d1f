// SPDX-License-Identifier: GPL-3.0-or-later
// The seam between the report and the extrapolation library: a function
// from a series' converged grids (h = Δ*, f = dp_star) to the contract's
// extrapolation JSON (docs/INTERFACE.md §4). The report calls the library through
// this, so tests can hand it any JSON of that shape.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

using Extrapolator =
    std::function<nlohmann::json(const std::vector<double>& h, const std::vector<double>& f)>;

struct ExtrapolatorSettings {
  std::string method = "capped";    // capped (default) | fm (PHYSICS.md §8) | eh14
  double p_low = 0.5, p_high = 2.1;  // power-law acceptance range
  std::string weights = "inverse_h"; // inverse_h | uniform (fm fits)
};

// extrap/extrapolation.h's extrapolate(), returned as to_json(result).
Extrapolator library_extrapolator(const ExtrapolatorSettings& settings);

}  // namespace gridfree
