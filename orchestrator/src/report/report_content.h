// SPDX-License-Identifier: GPL-3.0-or-later
// Everything a report shows, computed once and rendered three ways
// (Markdown, HTML, CSV + SVG files): series summaries with their
// extrapolations, one-factor differences, tables and charts.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report/differences.h"
#include "report/extrapolator.h"
#include "report/report_about.h"
#include "report/report_alignment.h"
#include "report/report_charts.h"
#include "report/report_data.h"
#include "report/report_ensembles.h"
#include "report/report_layout.h"
#include "report/series_summary.h"
#include "report/table.h"
#include "study/case_vocabulary.h"

namespace gridfree {

struct NamedTable {
  std::string file;     // CSV file name
  std::string title;    // section heading
  Table table;
  // Summary layout's grids and GCI tables: `table` holds the first rows, the
  // CSV is written series by series (report.cpp); this is the whole count.
  std::size_t total_rows = 0;
  std::size_t rows() const { return total_rows > table.rows.size() ? total_rows : table.rows.size(); }
  // The study's words (study/case_vocabulary.h): the reading note names the
  // case's quantity and h, its model-form factors and iterations in them.
  CaseVocabulary words = case_vocabulary(CaseKindId::particle_bed);
};

struct ReportContent {
  StudyReportData data;                    // as given, without its series (those are in `series`)
  ReportLayout layout = ReportLayout::full_page;  // report_layout.h: summary beyond kFullPageSeries series
  std::vector<SeriesSummary> series;
  std::vector<SeriesDifference> differences;
  NamedTable series_table, differences_table, cost_table, gci_table, grids_table, failures_table;
  NamedTable coverage_table;               // the coverage self-check (series_coverage.h)
  NamedTable verdict_count_table;          // verdicts per factor level (verdict_counts.h)
  // Full page: every chart; summary layout: the study-wide charts only (each
  // series' charts are on its page, report/series_page.h).
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

// The grids and GCI tables of the summary layout: the first rows of the
// whole table and its row count, without holding every row (48 600 grids
// take 85 MB as a Table); `of_series` makes the table of one series.
NamedTable head_of_series_tables(const std::vector<SeriesSummary>& series, std::string file, std::string title,
                                 const std::function<Table(const std::vector<SeriesSummary>&)>& of_series);

// Summary layout: series i's page, series/<slug>.html (report/series_page.cpp).
std::string series_page_file(const ReportContent& content, std::size_t i);

// The "About this case" sections: the generators' fixed texts
// (report_about.h), then the beds' structure (bed_about.h).
std::vector<AboutSection> study_about_sections(const ReportContent& content);

}  // namespace gridfree
