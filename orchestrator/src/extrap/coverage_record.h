// SPDX-License-Identifier: GPL-3.0-or-later
// What each method's interval was measured to cover, so that an interval
// travels with its record: the development corpus of published and
// exact-answer grid series (bench/coverage/corpus/, run by
// bench/coverage/corpus.py; docs/EXTRAPOLATION.md "Coverage on other codes'
// series"). `gridfree extrapolate` prints it as "coverage".
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "extrap/result.h"

namespace gridfree {

// One verdict class: windows judged, share covered by f₁ ± U₁ and f0 ± U₀.
struct ClassCoverage {
  std::string verdict;
  int windows = 0;
  double u1 = 0, u0 = 0;  // fractions
};

struct MeasuredCoverage {
  std::string method;    // averaged | capped | fm | eh14
  std::string corpus;    // what it was measured on
  std::string measured;  // date and command
  bool with_order = false;             // measured with each series' formal order declared (--order)
  std::vector<ClassCoverage> classes;  // the whole corpus
  std::string shortfall;  // where it falls below 95 %, in words ("" when nowhere)
};

// The record of `method`, measured without or with a declared order.
MeasuredCoverage measured_coverage(ExtrapolationMethod method, bool with_order);

// "method averaged (no formal order declared) was measured on the corpus to
// cover 98 % of converged windows with f₁ ± U₁ and 98 % with f0 ± U₀; short
// of 95 %: …" — for the verdict class given (empty when it prints no U).
std::string measured_coverage_sentence(ExtrapolationMethod method, bool with_order, const std::string& verdict);

// {method, order_declared, corpus, measured, classes: {verdict: {windows,
// u1, u0}}, shortfall}
nlohmann::ordered_json measured_coverage_json(ExtrapolationMethod method, bool with_order);

}  // namespace gridfree
