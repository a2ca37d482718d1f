// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the reader of result files read back (job/result.h): any bytes
// give a JobResult or an InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "core/json_limits.h"
#include "job/result.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)gridfree::result_from_json(gridfree::parse_json_text(text, "result.json"));
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
