// SPDX-License-Identifier: GPL-3.0-or-later
// Writes reports/<study>/: report.md, a self-contained report.html, CSV
// tables and SVG charts, from StudyReportData (no database access here).
#pragma once

#include <filesystem>
#include <vector>

#include "report/extrapolator.h"
#include "report/report_data.h"
#include "report/report_stop.h"

namespace gridfree {

struct ReportFiles {
  std::filesystem::path markdown, html;
  std::vector<std::filesystem::path> csv, svg;
};

// Regenerates every file of the report (atomically per file: temp + rename),
// extrapolating each series with the extrapolation library (settings from
// data.extrapolation_method, p_low, p_high). Temporary files of killed
// writers are removed first (report/atomic_file.h). `stop` is polled before
// every chart and during its PDF/PNG export: a stop throws ReportInterrupted
// (report/report_stop.h) within about 20 ms of a converter's poll.
ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir,
                               const StopRequested& stop = {});

// The same with a given extrapolator (tests, other extrapolation back-ends).
ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir,
                               const Extrapolator& extrapolate, const StopRequested& stop = {});

}  // namespace gridfree
