// SPDX-License-Identifier: GPL-3.0-or-later
// "$ref" resolution (core/schema_refs.h).
#include "core/schema_refs.h"

#include <stdexcept>

namespace gridfree {

SchemaNode resolve_ref(const SchemaNode& n, const std::string& ref, const SchemaFetch& fetch) {
  const auto hash = ref.find('#');
  const std::string doc_part = ref.substr(0, hash);
  const std::string fragment = hash == std::string::npos ? std::string() : ref.substr(hash + 1);
  const nlohmann::json* doc = doc_part.empty() ? n.doc : &fetch(doc_part);
  if (fragment.empty()) return {doc, doc};
  try {
    const nlohmann::json::json_pointer pointer(fragment);
    if (!doc->contains(pointer)) throw std::runtime_error("no such location");
    return {doc, &doc->at(pointer)};
  } catch (const std::exception& e) {
    throw std::runtime_error("schema $ref '" + ref + "' cannot be resolved: " + e.what());
  }
}

}  // namespace gridfree
