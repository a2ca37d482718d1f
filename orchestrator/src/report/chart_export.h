// SPDX-License-Identifier: GPL-3.0-or-later
// PDF and PNG copies of the report's SVG charts, made with rsvg-convert
// (Debian librsvg2-bin). Optional: without it the report says so and keeps
// the SVGs only (docs/REPORTS.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/report_stop.h"

namespace gridfree {

// rsvg-convert on PATH, or "" when it is not installed.
std::filesystem::path find_svg_converter();

// Writes X.pdf and X.png beside X.svg with `converter`; returns the file
// names written (those that failed are left out). The converter writes to
// ".X.pdf.tmp-<pid>-0" (renamed into place), which remove_stale_temporaries
// (report/atomic_file.h) removes once its process is gone. `stop` is polled
// every 20 ms while the converter runs: on a stop the converter is killed,
// its temporary file removed and ReportInterrupted thrown.
std::vector<std::string> export_chart(const std::filesystem::path& converter, const std::filesystem::path& svg,
                                      const StopRequested& stop = {});

}  // namespace gridfree
