// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a series from the files users bring (docs/INTERFACE.md §4, `gridfree
// extrapolate`): JSON {"h": [...], "f": [...]} or CSV with a header row
// naming the columns h and f (other columns are ignored, '#' starts a comment
// line). The result is validated and sorted by make_series.
#pragma once

#include <filesystem>
#include <string>

#include "extrap/series.h"

namespace gridfree {

// JSON text; problems are reported as "<source>: ..." or JSON pointers.
Series parse_series_json(const std::string& text, const std::string& source);

// CSV text; problems are reported as "<source>:<line>".
Series parse_series_csv(const std::string& text, const std::string& source);

// By extension (.json / .csv), otherwise by content (a leading '{' means JSON).
// A file that cannot be read is an InputError too.
Series read_series_file(const std::filesystem::path& path);

}  // namespace gridfree
