// SPDX-License-Identifier: GPL-3.0-or-later
// Coverage self-check (docs/EXTRAPOLATION.md "Coverage self-check"): does
// the uncertainty a procedure prints cover the answer the same procedure
// gives once more grids are added? Measured on the user's own series.
//
// For a series of n ≥ 6 grids (h ascending, finest first), the reference is
// f0 of all n grids. Every window of 4 ≤ m ≤ 8 consecutive grids among the
// n − 1 coarser ones (h_2 … h_n; the window sizes the promised rate was
// measured on) is extrapolated with the same settings; a window
// that prints an uncertainty is
//
//   covered   when |f0_ref − f_1w| ≤ U_1w   (the window's finest grid, f₁ ± U₁)
//   f0 covered when |f0_ref − f0_w| ≤ U0_w   (the window's f0 ± U₀)
//
// and its distance |f0_ref − f_1w| / U_1w is kept (≤ 1 covered). Coverage is
// k of n judged windows; below `promised` (the rate the procedure was
// measured to reach, docs/EXTRAPOLATION.md) it is a warning. The windows
// share grids, so k/n is not a binomial rate: one pre-asymptotic stretch of
// coarse grids can account for several misses.
//
// The reference is the same procedure on more grids, so a bias every window
// shares is invisible to the window comparison. The check therefore also
// carries the whole series' bias tests (bias_checks.h: observed against
// declared order, leave-one-out agreement); a failed test flags the series
// as a coverage below the promise does.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/result.h"

namespace gridfree {

// What a passing check shows and what it does not (with every check's JSON).
inline constexpr const char* kSelfCheckShows =
    "A passing check shows that the uncertainty of the series' coarser windows covered what the same procedure "
    "gives on all its grids, that the fits without its coarsest and without its finest grid agree, and (when "
    "one is declared) that the observed order agrees with the formal order. It does not show that f0 is the "
    "exact answer: an error every grid shares in the same proportion passes every one of these tests.";

// What the check needs of one extrapolation.
struct WindowFit {
  std::string verdict;                   // converged | pre-asymptotic | unreliable | insufficient_grids
  std::optional<double> f0, u0, f1, u1;  // u1: the finest grid's U; u0: f0's own uncertainty
  std::optional<bool> order_consistent, leave_one_out_agree;  // bias tests (empty: not made)
};

using WindowExtrapolator = std::function<WindowFit(const std::vector<double>& h, const std::vector<double>& f)>;

struct CoverageWindow {
  std::size_t first = 0, count = 0;  // grids first … first + count − 1 of the series (0 = finest)
  double h_fine = 0, h_coarse = 0;
  WindowFit fit;
  std::optional<double> distance;    // |f0_ref − f_1w| / U_1w
  std::optional<bool> covered, f0_covered;  // empty when the window prints no U
};

struct CoverageRules {
  std::size_t min_series = 6;  // grids a series needs for the check
  std::size_t min_window = 4;  // grids per window (the fit's minimum)
  std::size_t max_window = 8;  // the largest window the promise was measured on
  double promised = 0.95;      // coverage the procedure was measured to reach
};

struct CoverageCheck {
  std::string status;                 // checked | too_few_grids | no_reference
  std::optional<double> reference;    // f0 of the whole series
  std::string reference_verdict;
  std::vector<CoverageWindow> windows;
  int judged = 0, covered = 0, f0_covered = 0;
  double promised = 0.95;
  std::optional<bool> order_consistent, leave_one_out_agree;  // the whole series' bias tests

  // The one-line summary: "U₁ covered the answer in k of n coarser windows …".
  std::string summary() const;
  // True when judged windows exist and covered/judged < promised.
  bool below_promise() const;
  // True when a bias test of the whole series failed.
  bool bias_failed() const;
  // below_promise() or bias_failed(): the series is not `converged`.
  bool flagged() const;
};

// h ascending (finest first), as make_series returns it. `extrapolate` is
// called once for the whole series and once per window.
CoverageCheck coverage_self_check(const std::vector<double>& h, const std::vector<double>& f,
                                  const WindowExtrapolator& extrapolate, const CoverageRules& rules = {});

// A `converged` verdict whose series' check is flagged becomes
// `pre-asymptotic` (the check's summary as its reason, the next finer grid
// h_1/r named); h ascending. Other verdicts and passing checks are left.
void demote_if_flagged(const CoverageCheck& check, const std::vector<double>& h, Verdict& v,
                       const std::string& h_symbol = "Δ*");

// The numbers the check needs from a library extrapolation.
WindowFit window_fit(const ExtrapolationResult& r);

// JSON of docs/INTERFACE.md §4 "self_check": status, reference,
// reference_verdict, judged, covered, f0_covered, promised, below_promise,
// order_consistent, leave_one_out_agree, flagged, summary, shows and windows[{h_fine, h_coarse, n_grids, verdict, f0, u0, f1, u1,
// distance, covered, f0_covered}] (null where not computed).
nlohmann::ordered_json to_ordered_json(const CoverageCheck& check);

// The inverse, for a check stored as that JSON (the database's
// series.coverage_json); a missing or mistyped member is left at its default.
CoverageCheck coverage_from_json(const nlohmann::json& j);

}  // namespace gridfree
