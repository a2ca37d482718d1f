// Writes reports/<study>/: report.md, a self-contained report.html, CSV
// tables and SVG charts, from StudyReportData (no database access here).
#pragma once

#include <filesystem>
#include <vector>

#include "report/extrapolator.h"
#include "report/report_data.h"

namespace gridfree {

struct ReportFiles {
  std::filesystem::path markdown, html;
  std::vector<std::filesystem::path> csv, svg;
};

// Regenerates every file of the report (atomically per file: temp + rename),
// extrapolating each series with the extrapolation library (settings from
// data.extrapolation_method, p_low, p_high).
ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir);

// The same with a given extrapolator (tests, other extrapolation back-ends).
ReportFiles write_study_report(const StudyReportData& data, const std::filesystem::path& out_dir,
                               const Extrapolator& extrapolate);

}  // namespace gridfree
