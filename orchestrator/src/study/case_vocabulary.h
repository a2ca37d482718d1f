// SPDX-License-Identifier: GPL-3.0-or-later
// How a kind of case names what the study measures (docs/REPORTS.md "Words
// of the case"): the symbol and meaning of its cell size h, the name of its
// quantity, what one iteration of its solver is and whether the results
// carry iteration counts, and which model-form factors its series vary.
// The report, its charts, the verdict's advice and `plan` take their words
// from here instead of asking "is it external?" each time, so a report of
// an OpenFOAM case never speaks of particles, Δ* or drag laws.
//
//   particle bed (the worker's own case): Δ* = cell size / particle
//     diameter, DP* = Δp / (ρ_g U_0²), outer SIMPLE iterations (counted),
//     model form = drag law, filter width, particle configuration, and the
//     published reference (Fullmer & Musser 2018: RDE < 4 % everywhere).
//   external template: h as the case declares it ("h = 0.1 / N"), the
//     quantity's own name, description and units, solver iterations only
//     when results report them, no model-form factors of its own.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gridfree {

enum class CaseKindId { particle_bed, external };

struct CaseVocabulary {
  CaseKindId kind = CaseKindId::particle_bed;
  std::string h_symbol;          // "Δ*" | "h"
  std::string h_meaning;         // axis title: "Δ* (cell size / particle diameter)" | "h = 0.1 / N"
  std::string quantity_symbol;   // "DP*" | the quantity's name ("mean_u2")
  std::string quantity_meaning;  // axis title: "DP* = Δp / (ρ_{g} U_{0}^{2})" | "mean_u2: … [m^2/s^2]"
  std::string h_column, value_column;  // CSV names: "delta_star", "dp_star" | "h", "value"
  bool cells_per_direction = true;     // grids have nx × ny × nz cells (an external case declares a count)
  bool particle_factors = true;        // series vary convection, filter width, drag, deposition
  std::string iteration;         // "outer iteration" | "iteration"
  bool iterations_counted = true;  // results carry iteration counts (an external code's: when it reports them)
  std::string model_form;        // factors a study varies to see model form: "" when the case has none
  // The factors whose one-level difference between two ensemble
  // configurations is model form (empty: any one factor), and how the
  // budget's rule names them.
  std::vector<std::string> model_form_factors;
  std::string value_noun;        // "DP*" | "value of the series' quantity"
  std::string grid_value_noun;   // "DP*" | "value (h as the study declares it)"
  // Axis titles where a chart is small (the GCI chart): the symbol where it
  // is defined elsewhere in the report (Δ*, DP*), else the declared meaning.
  std::string compact_h_axis, compact_value_axis;
  std::string model_form_rule;   // "drag law or filter width" | "one of the study's factors (same quantity)"
  std::string reference_rde;     // a published RDE to compare with: "" when none applies
};

// The words of a kind of case; an external case's h and quantity meanings
// are its declared ones (pass them; "" keeps the bare symbol).
CaseVocabulary case_vocabulary(CaseKindId kind, const std::string& h_meaning = {},
                               const std::string& quantity_name = {}, const std::string& quantity_meaning = {});

// The kind of a study's cases from its definition as stored: external when
// its first case (after "extends") has an "external" section.
CaseKindId case_kind_id_of(const nlohmann::json& study_definition);

}  // namespace gridfree
