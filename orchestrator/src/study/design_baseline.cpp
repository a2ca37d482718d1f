// SPDX-License-Identifier: GPL-3.0-or-later
// The design's baseline object (see design_baseline.h).
#include "study/design_baseline.h"

namespace gridfree {

const nlohmann::json* one_at_a_time_baseline(const nlohmann::json& doc, ProblemList& problems) {
  const auto d = doc.find("design");
  if (d == doc.end() || (d->is_string() && *d == "factorial")) return nullptr;
  if (!d->is_object() || !d->contains("one_at_a_time") || !(*d)["one_at_a_time"].is_object()) {
    problems.add_once("/design", "must be \"factorial\" or {\"one_at_a_time\": {baseline}}");
    return nullptr;
  }
  return &(*d)["one_at_a_time"];
}

}  // namespace gridfree
