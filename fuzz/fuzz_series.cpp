// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the series readers of `gridfree extrapolate` (extrap/series_io.h):
// the first byte picks JSON or CSV, the rest is the text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "extrap/series_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] & 1) (void)gridfree::parse_series_json(text, "series.json");
    else (void)gridfree::parse_series_csv(text, "series.csv");
  } catch (const gridfree::InputError&) {
  }
  return 0;
}
