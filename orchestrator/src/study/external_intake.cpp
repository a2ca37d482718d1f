// SPDX-License-Identifier: GPL-3.0-or-later
// record_collect_spec (study/external_intake.h).
#include "study/external_intake.h"

namespace gridfree {

void record_collect_spec(const nlohmann::json& spec, std::string& result_json) {
  if (result_json.empty() || !spec.is_object()) return;
  const auto c = spec.find("case");
  if (c == spec.end() || !c->is_object() || !c->contains("external")) return;
  const nlohmann::json& ext = (*c)["external"];
  if (!ext.is_object() || !ext.contains("collect")) return;
  auto doc = nlohmann::json::parse(result_json, nullptr, false);
  if (!doc.is_object()) return;
  doc["collected_with"] = ext["collect"];
  result_json = doc.dump();
}

}  // namespace gridfree
