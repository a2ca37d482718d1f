// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a series from the files users bring (docs/INTERFACE.md §4, `gridfree
// extrapolate`): JSON {"h": [...], "f": [...]} or CSV with a header row
// naming the columns h and f (other columns are ignored, '#' starts a comment
// line). The result is validated and sorted by make_series.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "extrap/series.h"

namespace gridfree {

// JSON text; problems are reported as "<source>: ..." or JSON pointers.
Series parse_series_json(const std::string& text, const std::string& source);

// CSV text; problems are reported as "<source>:<line>".
Series parse_series_csv(const std::string& text, const std::string& source);

// Most points a series file may hold (docs/LIMITS.md "gridfree extrapolate").
// The power-law fit scans 2 × 2 000 orders over every point (extrap/power_fit.h),
// so its time grows as the points: about 0.2 ms a point, 2 s at this limit;
// a grid study has tens of grids.
inline constexpr std::size_t kMaxSeriesPoints = 10000;

// By extension (.json / .csv), otherwise by content (a leading '{' means JSON).
// A file that cannot be read, or with more than kMaxSeriesPoints points, is
// an InputError too.
Series read_series_file(const std::filesystem::path& path);

}  // namespace gridfree
