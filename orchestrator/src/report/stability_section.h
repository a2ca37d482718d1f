// SPDX-License-Identifier: GPL-3.0-or-later
// The report's "Where methods fail" section (docs/REPORTS.md, stability
// map), kept out of the page layout so that it hooks in with one call per
// rendering:
//   - HTML: the map as an inline SVG (outcome per cell, the reason on
//     hover as the cell's <title>), the same map as a table (shown in
//     print, where the SVG is hidden), and the per-series lines;
//   - Markdown: the table and the lines;
//   - files: stability.csv (one row per grid: outcome, outer iterations,
//     reason) and stability_series.csv (one row per series: the line, the
//     GCI's usable triplets beside least squares), and the map as
//     stability_map.svg.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/report.h"
#include "report/report_content.h"
#include "report/stability_map.h"
#include "report/table.h"

namespace gridfree {

inline constexpr const char* kStabilityCsv = "stability.csv";
inline constexpr const char* kStabilitySeriesCsv = "stability_series.csv";
inline constexpr const char* kStabilitySvg = "stability_map.svg";

// Every grid of every series (no cap): series, Δ*, cells, outcome, outer
// iterations, reason, job hash.
Table stability_grid_table(const std::vector<SeriesSummary>& series);
// One row per series of the map (capped as the map): its line and tally.
Table stability_series_table(const StabilityMap& map);
// The map as a table: one row per series, one column per Δ*, the cell the
// outcome (converged: "✓ <outer iterations>").
Table stability_wide_table(const StabilityMap& map);
// The map as an SVG document fragment (<svg>…</svg>).
std::string stability_svg(const StabilityMap& map);

std::string stability_section_html(const ReportContent& content);
std::string stability_section_markdown(const ReportContent& content);
// Writes stability.csv, stability_series.csv (listed in files.csv) and
// stability_map.svg into dir, each atomically.
void write_stability_files(const ReportContent& content, const std::filesystem::path& dir, ReportFiles& files);

}  // namespace gridfree
