// SPDX-License-Identifier: GPL-3.0-or-later
// The words of each kind of case (see case_vocabulary.h).
#include "study/case_vocabulary.h"

#include "study/case_extends.h"

namespace gridfree {

CaseVocabulary case_vocabulary(CaseKindId kind, const std::string& h_meaning, const std::string& quantity_name,
                               const std::string& quantity_meaning) {
  CaseVocabulary v;
  v.kind = kind;
  if (kind == CaseKindId::particle_bed) {
    v.h_symbol = "Δ*";
    v.h_meaning = "Δ* (cell size / particle diameter)";
    v.quantity_symbol = "DP*";
    v.quantity_meaning = "DP* = Δp / (ρ_{g} U_{0}^{2})";
    v.h_column = "delta_star";
    v.value_column = "dp_star";
    v.iteration = "outer iteration";
    v.iterations_counted = true;
    v.model_form = "drag law, filter width, particle configuration";
    v.model_form_factors = {"drag", "fwhm_dp"};
    v.model_form_rule = "drag law or filter width";
    v.value_noun = v.quantity_symbol;
    v.grid_value_noun = v.quantity_symbol;
    v.compact_h_axis = v.h_symbol;
    v.compact_value_axis = v.quantity_symbol;
    v.reference_rde = "FM18 found < 4% everywhere";
    return v;
  }
  v.h_symbol = "h";
  v.h_meaning = h_meaning.empty() ? "h" : h_meaning;
  v.quantity_symbol = quantity_name.empty() ? "value" : quantity_name;
  v.quantity_meaning = quantity_meaning.empty() ? v.quantity_symbol : quantity_meaning;
  v.h_column = "h";
  v.value_column = "value";
  v.cells_per_direction = false;
  v.particle_factors = false;
  v.iteration = "iteration";
  v.iterations_counted = false;  // the caller sets it from the results
  v.model_form_rule = "one of the study's factors (same quantity)";
  v.value_noun = "value of the series' quantity";
  v.grid_value_noun = "value (h as the study declares it)";
  v.compact_h_axis = v.h_meaning;
  v.compact_value_axis = v.quantity_meaning;
  return v;
}

CaseKindId case_kind_id_of(const nlohmann::json& study_definition) {
  if (!study_definition.is_object() || !study_definition.contains("cases") || !study_definition["cases"].is_object() ||
      study_definition["cases"].empty())
    return CaseKindId::particle_bed;
  const nlohmann::json c = resolved_case(study_definition, study_definition["cases"].begin().key());
  return c.is_object() && c.contains("external") ? CaseKindId::external : CaseKindId::particle_bed;
}

}  // namespace gridfree
