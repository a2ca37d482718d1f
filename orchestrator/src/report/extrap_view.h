// SPDX-License-Identifier: GPL-3.0-or-later
// The report's view of one series' extrapolation, read from the JSON form
// of the extrapolation result (docs/INTERFACE.md §4, `gridfree extrapolate`):
//
//   {"status", "method", "f0", "u0", "p", "sigma_re", "data_range", "fs",
//    "fits": {"power": {f0, p, c, sigma, p_found}, "mixed": {f0, c1, c2, sigma}},
//    "grids": [{h, f, fhat, u, rde}], "gci": [{h[3], p, f_ext, gci_fine, convergence, status}]}
//
// Depending only on that JSON keeps the report independent of the
// extrapolation library's C++ types. Absent keys and nulls become empty
// optionals; a key of the wrong type is an InputError naming its JSON pointer.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

struct ExtrapolatedGrid {
  double h = 0, f = 0;
  std::optional<double> fhat, u, rde;
};

struct GciView {
  std::array<double, 3> h{};              // finest first
  std::optional<double> p, f_ext, gci_fine;
  std::string convergence;                // monotonic | oscillatory | divergent | ...
  std::string status;
};

struct PowerFitView {
  std::optional<double> f0, p, c, sigma;
  bool p_found = false;
};

struct MixedFitView {
  std::optional<double> f0, c1, c2, sigma;
};

struct ExtrapolationView {
  std::string status;                     // ok | insufficient_grids | (other words passed through)
  std::string method;                     // power | capped_power | mixed | constant | eh14_…
  std::optional<double> f0, p, sigma_re, data_range, fs;
  std::optional<double> u0;               // f0's own uncertainty (docs/EXTRAPOLATION.md "U₀")
  PowerFitView power;
  MixedFitView mixed;
  std::vector<ExtrapolatedGrid> grids;    // h ascending
  std::vector<GciView> gci;            // finest triplet first
  std::vector<std::string> notes;         // plain-language remarks, when given
  std::string verdict;                    // /verdict/value (docs/EXTRAPOLATION.md "Verdicts"), "" if absent
  std::vector<std::string> verdict_reasons;
  std::optional<double> next_h;           // /verdict/next_h: suggested finer grid

  // σ_RE / R_f (PHYSICS.md §8; < 1 = good fit); empty when either is missing or R_f = 0.
  std::optional<double> fit_quality() const;
  // The grid entry at h (relative tolerance 1e-9), if any.
  const ExtrapolatedGrid* grid_at(double h) const;
};

ExtrapolationView from_json(const nlohmann::json& json);

}  // namespace gridfree
