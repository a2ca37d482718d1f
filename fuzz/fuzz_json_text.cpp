// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the JSON text limits and the schema validator (core/json_limits.h,
// core/schema_validation.h): any bytes either fail with an InputError or
// parse, and any parsed document validates against every shipped schema
// without crashing.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "core/json_limits.h"
#include "core/schema_validation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const nlohmann::json doc = gridfree::parse_json_text(text, "fuzz.json");
    for (const char* schema : {"job.schema", "study.schema", "particles.schema", "result.schema"})
      (void)gridfree::validate_against_schema(doc, schema);
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
