// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the job reader (job/job_spec.h: limits, schema, semantic and
// plausibility checks): any bytes give a JobSpec or an InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/input_error.h"
#include "core/json_limits.h"
#include "job/job_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)gridfree::parse_job(gridfree::parse_json_text(text, "job.json"), "/nonexistent");
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
