// SPDX-License-Identifier: GPL-3.0-or-later
// Report labels of external series (report/external_labels.h).
#include "report/external_labels.h"

#include "report/text_format.h"
#include "study/case_extends.h"

namespace gridfree {

std::string external_quantity_label(const std::string& name, const std::string& description,
                                    const std::string& units) {
  std::string out = name;
  if (!description.empty()) out += ": " + description;
  if (!units.empty() && units != "1") out += " [" + units + "]";
  return out;
}

std::string external_h_label(const nlohmann::json& h) {
  if (h.is_string()) return "h = " + h.get<std::string>();
  if (h.is_object()) {
    const int dim = h.value("dim", 3);
    const double volume = h.value("volume", 1.0);
    return "h = (V / cells)^(1/" + std::to_string(dim) + "), cells = " + h.value("cells", std::string("?")) +
           ", V = " + format_g(volume, 6);
  }
  return "h";
}

void label_external_series(const nlohmann::json& definition, const SeriesKey& key, SeriesData& sd) {
  sd.quantity = key.quantity;
  sd.levels = key.levels;
  // The case as the study resolved it: its `external` section may be
  // inherited through "extends".
  const nlohmann::json c = resolved_case(definition, key.case_name);
  const nlohmann::json ext = c.is_object() ? c.value("external", nlohmann::json::object()) : nlohmann::json::object();
  nlohmann::json q = nlohmann::json::object();
  if (ext.contains("collect") && ext["collect"].is_object() && ext["collect"].contains("quantities") &&
      ext["collect"]["quantities"].is_object() && ext["collect"]["quantities"].contains(key.quantity))
    q = ext["collect"]["quantities"][key.quantity];
  sd.quantity_label = external_quantity_label(key.quantity, q.is_object() ? q.value("description", "") : "",
                                              q.is_object() ? q.value("units", "") : "");
  sd.h_label = external_h_label(ext.is_object() ? ext.value("h", nlohmann::json()) : nlohmann::json());
}

}  // namespace gridfree
