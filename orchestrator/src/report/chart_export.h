// PDF and PNG copies of the report's SVG charts, made with rsvg-convert
// (Debian librsvg2-bin). Optional: without it the report says so and keeps
// the SVGs only (docs/REPORTS.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gridfree {

// rsvg-convert on PATH, or "" when it is not installed.
std::filesystem::path find_svg_converter();

// Writes X.pdf and X.png beside X.svg with `converter`; returns the file
// names written (those that failed are left out).
std::vector<std::string> export_chart(const std::filesystem::path& converter, const std::filesystem::path& svg);

}  // namespace gridfree
