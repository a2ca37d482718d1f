// SPDX-License-Identifier: GPL-3.0-or-later
// Extrapolation of one grid-convergence series to h → 0 with an uncertainty
// for every grid (PHYSICS.md §8), plus the classic three-grid GCI for every
// consecutive triplet for contrast [Celik et al. 2008]. The API the study
// report, the scheduler and `gridfree extrapolate` use.
//
//   n ≥ 4, varying f : the chosen procedure (fm_uncertainty.h or eh14.h)
//   n ≥ 4, constant f: method "constant", f0 = f, U = 0, RDE = 0
//   n < 4            : status "insufficient_grids" (no fits, no uncertainty)
//   always           : data_range (n ≥ 2) and the GCI triplets (n ≥ 3)
//
// JSON (docs/INTERFACE.md §4): to_json gives status, method, f0, p, sigma_re,
// data_range, fs, fits.power{f0,p,c,sigma,p_found}, fits.mixed{f0,c1,c2,sigma},
// grids[{h,f,fhat,u,rde}] (h ascending), gci[{h:[3],p,f_ext,gci_fine,
// convergence,status}] (finest first), plus sigma_over_range, n_grids, notes,
// extra GCI fields, and for EH14 fits.first, fits.second and "eh14" (the
// branch taken). Numbers that cannot be computed are null.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/result.h"
#include "extrap/series.h"

namespace gridfree {

// Validates h and f (InputError with JSON pointers /h/i, /f/i) and options
// (InputError at "--p-range"), then extrapolates. Input in any order.
ExtrapolationResult extrapolate(const std::vector<double>& h, const std::vector<double>& f,
                                const ExtrapolationOptions& opts = {});

// Same for an already validated, sorted series.
ExtrapolationResult extrapolate(const Series& s, const ExtrapolationOptions& opts = {});

// Throws InputError when p_low ≥ p_high, either is not finite, or the p search
// range is not 0 < p_min < p_max.
void validate_options(const ExtrapolationOptions& opts);

// "averaged" | "capped" | "fm" | "eh14" -> method; anything else is an InputError at `where`.
ExtrapolationMethod parse_method(const std::string& name, const std::string& where);

nlohmann::json to_json(const ExtrapolationResult& r);
nlohmann::ordered_json to_ordered_json(const ExtrapolationResult& r);  // keys in the order of docs/INTERFACE.md

}  // namespace gridfree
