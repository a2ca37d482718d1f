// SPDX-License-Identifier: GPL-3.0-or-later
// Choosing a case kind (study/case_kind.h): the only place that asks which kind.
#include "study/case_kind.h"

namespace gridfree {

const CaseKind& case_kind(const SeriesKey& key) { return key.external() ? external_kind() : particle_bed_kind(); }

const CaseKind& case_kind(const Study& study) { return study.external() ? external_kind() : particle_bed_kind(); }

const CaseKind& case_kind_of_job(const nlohmann::json& spec) {
  const bool external =
      spec.is_object() && spec.contains("case") && spec["case"].is_object() && spec["case"].contains("external");
  return external ? external_kind() : particle_bed_kind();
}

const CaseKind& case_kind_of_definition(const nlohmann::json& definition) {
  if (definition.is_object() && definition.contains("cases") && definition["cases"].is_object())
    for (const auto& [name, c] : definition["cases"].items())
      if (c.is_object() && c.contains("external")) return external_kind();
  return particle_bed_kind();
}

}  // namespace gridfree
