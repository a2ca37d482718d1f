// Everything a report shows, computed once and rendered three ways
// (Markdown, HTML, CSV + SVG files): series summaries with their
// extrapolations, one-factor differences, tables and charts.
#pragma once

#include <string>
#include <vector>

#include "report/differences.h"
#include "report/extrapolator.h"
#include "report/report_alignment.h"
#include "report/report_charts.h"
#include "report/report_data.h"
#include "report/report_ensembles.h"
#include "report/series_summary.h"
#include "report/table.h"

namespace gridfree {

struct NamedTable {
  std::string file;     // CSV file name
  std::string title;    // section heading
  Table table;
};

struct ReportContent {
  StudyReportData data;                    // as given (series in the given order)
  std::vector<SeriesSummary> series;
  std::vector<SeriesDifference> differences;
  NamedTable series_table, differences_table, cost_table, gci_table, grids_table, failures_table;
  NamedTable coverage_table;               // the coverage self-check (series_coverage.h)
  std::vector<NamedChart> charts;
  std::vector<AlignmentLine> alignment;    // empty unless the study ran the alignment check
  NamedTable alignment_table;
  EnsembleSection ensembles;               // empty without ensembles (report_ensembles.h)
  std::string export_note;                 // why charts have no PDF/PNG copies, if they have none

  // Counts over all grids of all series.
  int grids_total() const;
  int grids_converged() const;
  int grids_failed() const;
  int grids_pending() const;
};

ReportContent build_report_content(const StudyReportData& data, const Extrapolator& extrapolate);

// Report documents; chart files are referenced by their NamedChart::file.
std::string render_markdown(const ReportContent& content);
std::string render_html(const ReportContent& content);  // self-contained: CSS and SVG inline

}  // namespace gridfree
