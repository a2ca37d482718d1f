// SPDX-License-Identifier: GPL-3.0-or-later
// Options and result of extrapolating one series (PHYSICS.md §8, docs/INTERFACE.md §4).
// Numbers that cannot be computed are empty optionals (JSON null).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "extrap/gci.h"
#include "extrap/power_fit.h"
#include "extrap/series.h"
#include "extrap/verdict_types.h"

namespace gridfree {

enum class ExtrapolationMethod {
  kAveraged,  // capped, widened to the spread of f0 over the admissible fits
              // (default, docs/EXTRAPOLATION.md "Default procedure", model_average.h)
  kCapped,  // FM with observed orders above p_high capped at p_high
  kFm,      // Fullmer & Musser (2018), PHYSICS.md §8, as published
  kEh14,    // Eça & Hoekstra (2014), full procedure
};

struct ExtrapolationOptions {
  ExtrapolationMethod method = ExtrapolationMethod::kAveraged;
  // Accepted observed orders: FM uses the power law iff p_low ≤ p ≤ p_high
  // (capped: p > p_high → the fit f0 + c h^p_high);
  // EH14 uses Fs = 1.25 iff p_low ≤ p < p_high (and σ < Δφ).
  double p_low = 0.5, p_high = 2.1;
  Weighting weights = Weighting::kInverseH;  // FM fits (EH14 tries both)
  PowerSearch search;                        // p scan range and density
  // Declared formal order of the discretization (`--order`, a study's
  // extrapolation.expected_order); empty: none declared (bias_checks.h).
  std::optional<double> expected_order;
  // The leave-one-out test of bias_checks.h (default on; off reproduces the
  // procedure before it, for comparison: `--no-leave-one-out`).
  bool leave_one_out = true;
  // `averaged` only: an `unreliable` result's U at least 3 Δφ (model_average.h;
  // default on; off reproduces the method before it: `--no-range-floor`).
  bool unreliable_range_floor = true;
  // How the verdict's advice names the cell size ("add the next finer grid
  // Δ* = 0.39"): the case's own symbol (report/case_vocabulary.h), "h" for
  // an external case.
  std::string h_symbol = "Δ*";
};

// One fit as reported under "fits". Unused members stay empty.
struct FitSummary {
  std::optional<double> f0, p, c, c1, c2, sigma;
  std::optional<bool> p_found;   // power law only
  std::optional<bool> weighted;  // EH14 only: which of the two variants won
};

struct GridUncertainty {
  double h = 0, f = 0;
  std::optional<double> fhat, u, rde;
};

// Which rules of EH14 applied (EH14 Appendix A).
struct Eh14Branch {
  std::string order;           // low_order | expected_order | high_order | no_order
  std::string scatter;         // sigma_below_data_range | sigma_at_least_data_range
  std::string error_estimate;  // fit used for ε_φ: power|first|second|mixed _ weighted|unweighted
  std::optional<double> p;     // observed order of the selected power-law fit
};

// The bias checks of bias_checks.h: declared order and leave-one-out fits.
struct BiasCheck {
  std::optional<double> expected_order, order_ratio, order_factor;  // P, p/P, Xing & Stern FS
  std::optional<bool> order_consistent;                             // empty: no order declared
  std::optional<double> f0_without_coarsest, f0_without_finest;
  std::optional<bool> leave_one_out_agree;                          // empty: too few grids
};

// The fits whose f0 the `averaged` method's uncertainty holds (model_average.h).
struct ModelSpreadSummary {
  std::vector<std::string> fits;
  std::vector<double> f0;
};

struct ExtrapolationResult {
  std::string status = "ok";           // ok | insufficient_grids
  std::optional<std::string> method;   // power | mixed | constant | eh14_<fit>_<weighting>
  std::optional<double> f0, p, sigma_re, data_range, fs, sigma_over_range;
  std::optional<double> u0;            // f0's own uncertainty (docs/EXTRAPOLATION.md "U₀")
  std::optional<FitSummary> power, mixed, first, second;  // first/second: EH14 only
  std::optional<FitSummary> capped;    // capped only: f0 + c h^p_high when p > p_high
  std::vector<GridUncertainty> grids;  // h ascending
  std::vector<GciTriplet> gci;         // consecutive triplets, finest first
  std::optional<Eh14Branch> eh14;
  std::vector<std::string> notes;      // plain-language remarks for reports
  std::optional<ModelSpreadSummary> model_spread;  // averaged only
  BiasCheck bias;                      // bias_checks.h (filled for every fitted series)
  Verdict verdict;                     // one word and its reasons (verdict.h)
};

}  // namespace gridfree
