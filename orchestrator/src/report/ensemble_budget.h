// SPDX-License-Identifier: GPL-3.0-or-later
// The uncertainty budget of an ensemble (docs/EXTRAPOLATION.md "Ensembles"),
// FM18's Fig. 3 comparison: at each Δ* of a configuration C, three relative
// magnitudes side by side —
//
//   discretization   D(Δ*) = ensemble-mean RDE of C at Δ*   (U/|f0|, ~95 % band)
//   model form       M     = max over configurations C' of the same ensemble
//                            that differ from C in drag or in fwhm_dp only
//                            (an external study: in one of its own factors,
//                            same quantity) of
//                            2 |x̄_C − x̄_C'| / |x̄_C + x̄_C'|   (x̄ = ensemble-mean f0)
//   instance spread  S     = s/|x̄| of C's f0 over the instances
//
// and the largest of those present dominates at that Δ*. A source that
// cannot be computed (no second drag law or filter width; fewer than two
// instances with f0) is absent and takes no part in the comparison.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/ensemble_stats.h"

namespace gridfree {

struct ModelFormDifference {
  std::size_t a = 0, b = 0;          // indices into the configs
  std::string factor;                 // drag | fwhm_dp | an external study's factor
  std::string value_a, value_b;
  std::optional<double> relative;     // 2|x̄a − x̄b| / |x̄a + x̄b|
};

// Pairs of configurations of one ensemble differing in exactly one of drag,
// fwhm_dp (convection and deposition equal); external configurations of
// one quantity differing in exactly one factor level.
std::vector<ModelFormDifference> model_form_differences(const std::vector<EnsembleConfig>& configs);

struct BudgetRow {
  std::size_t config = 0;
  double delta_star = 0;
  std::optional<double> discretization;   // D
  std::optional<double> model_form;       // M
  std::string model_form_pair;            // "drag bvk vs gidaspow_blend"
  std::optional<double> spread;           // S
  std::string dominant;                   // discretization | model form | instance spread | "" (none)
};

// One row per (configuration, Δ*), configurations in order, Δ* ascending.
std::vector<BudgetRow> budget_rows(const std::vector<EnsembleConfig>& configs,
                                   const std::vector<ModelFormDifference>& differences);

// The largest of the present sources: "discretization", "model form",
// "instance spread", or "" when none is present. Ties go to the first in that order.
std::string dominant_source(const std::optional<double>& d, const std::optional<double>& m,
                            const std::optional<double>& s);

// One sentence per configuration: the ranges of Δ* over which each source
// dominates, with the numbers at the finest and coarsest Δ* of each range.
std::vector<std::string> budget_sentences(const std::vector<EnsembleConfig>& configs,
                                          const std::vector<BudgetRow>& rows);

}  // namespace gridfree
