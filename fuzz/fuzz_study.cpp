// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the study reader (study/study.h): any bytes give a Study or an
// InputError (grids, cases, factors and designs included).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "core/json_limits.h"
#include "study/study.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)gridfree::parse_study_document(gridfree::parse_json_text(text, "study.json"), "/nonexistent");
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
