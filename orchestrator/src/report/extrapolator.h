// SPDX-License-Identifier: GPL-3.0-or-later
// The seam between the report and the extrapolation library: a function
// from a series' converged grids (h = Δ*, f = dp_star) to the contract's
// extrapolation JSON (docs/INTERFACE.md §4). The report calls the library through
// this, so tests can hand it any JSON of that shape.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

using Extrapolator =
    std::function<nlohmann::json(const std::vector<double>& h, const std::vector<double>& f)>;

struct ExtrapolatorSettings {
  std::string method = "averaged";  // averaged (default) | capped | fm (PHYSICS.md §8) | eh14
  double p_low = 0.5, p_high = 2.1;  // power-law acceptance range
  std::string weights = "inverse_h"; // inverse_h | uniform (fm fits)
  std::optional<double> expected_order;  // declared formal order (extrap/bias_checks.h)
  std::string h_symbol = "Δ*";           // the case's cell-size symbol in the verdict's advice (study/case_vocabulary.h)
};

// extrap/extrapolation.h's extrapolate(), returned as to_json(result).
Extrapolator library_extrapolator(const ExtrapolatorSettings& settings);

// One line naming the method, the corpus it was measured on and its measured
// coverage per verdict class (extrap/coverage_record.h); "" for an unknown method.
std::string measured_coverage_line(const std::string& method, bool order_declared);

}  // namespace gridfree
