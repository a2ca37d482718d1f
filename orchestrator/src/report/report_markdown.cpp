// SPDX-License-Identifier: GPL-3.0-or-later
// report.md: summary, tables, and links to the SVG charts beside it.
#include <algorithm>
#include <limits>
#include <string>

#include "report/adaptive_section.h"
#include "report/report_about.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/series_coverage.h"
#include "report/stability_section.h"
#include "report/text_format.h"
#include "report/first_screen.h"
#include "report/verdict_counts.h"

namespace gridfree {

namespace {

// At most `max_rows` rows; a longer table says so and links its CSV.
std::string table_section(const NamedTable& t, const std::string& empty_text,
                          std::size_t max_rows = std::numeric_limits<std::size_t>::max()) {
  std::string out = "## " + t.title + "\n\n";
  const std::string note = reading_note(t.file, t.words);
  if (!note.empty()) out += note + "\n\n";
  const bool cut = t.rows() > std::min(max_rows, t.table.rows.size());
  out += t.table.rows.empty() ? empty_text + "\n" : to_markdown(cut ? first_rows(t.table, max_rows) : t.table);
  out += cut ? "\nThe first " + std::to_string(std::min(max_rows, t.table.rows.size())) + " of " +
                   std::to_string(t.rows()) +
                   " rows; every row in [" + t.file + "](" + t.file + ")\n\n"
             : "\nCSV: [" + t.file + "](" + t.file + ")\n\n";
  return out;
}

void verdict_lines(std::string& out, const VerdictItem& v, const std::string& href = {}) {
  out += "- **" + (href.empty() ? v.label : "[" + v.label + "](" + href + ")") + "**: **" + v.verdict + "** — " +
         v.headline + "\n";
  for (const auto& r : v.reasons) out += "  - " + r + "\n";
  for (const auto& n : v.notes) out += "  - Note: " + n + "\n";
}

std::string chart_link(const NamedChart& c) {
  return "![" + md_cell(c.chart.title) + "](" + c.file + ")\n\n" + c.caption + "\n\n";
}

}  // namespace

std::string render_markdown(const ReportContent& c) {
  const bool summary = c.layout == ReportLayout::summary;
  const std::size_t cap = summary ? kShownRows : std::numeric_limits<std::size_t>::max();
  std::string out = "# Grid-convergence report: " + c.data.study_name + "\n\n";
  out += first_screen_markdown(c);  // the answer first (first_screen.h)
  for (const auto& [key, value] : summary_items(c)) out += "- **" + key + ":** " + value + "\n";
  out += "\n";
  out += "## Verdicts\n\n" + reading_note("verdicts") + "\n\n";
  if (summary) {
    out += to_markdown(c.verdict_count_table.table) + "\nCSV: [" + c.verdict_count_table.file + "](" +
           c.verdict_count_table.file + ")\n\n### Worst series\n\n";
    for (std::size_t i : worst_series(c.series, kWorstSeries)) verdict_lines(out, verdict_item(c.series[i]), series_page_file(c, i));
  } else {
    for (const auto& v : verdict_items(c)) verdict_lines(out, v);
    out += std::string(c.verdict_count_table.table.rows.size() > 1 ? "\nCounts per factor level: ["
                                                                    : "\nCounts: [") +
           c.verdict_count_table.file + "](" + c.verdict_count_table.file + ")\n";
  }
  out += "\n";
  out += adaptive_section_markdown(c.data.adaptive_decisions);
  for (const auto& a : study_about_sections(c)) {
    out += "## " + a.title + "\n\n";
    for (const auto& p : a.paragraphs) out += p + "\n\n";
  }
  out += ensembles_markdown(c);
  out += table_section(c.series_table, "No series.", cap);
  out += table_section(c.differences_table, "No two series differ in exactly one factor.", cap);
  out += table_section(c.cost_table, "No series has an extrapolation yet.", cap);
  out += table_section(c.coverage_table,
                       "No series checked: " + coverage_not_made(c.series) + ".", cap);
  out += "## Charts\n\n";
  if (!c.export_note.empty()) out += c.export_note + "\n\n";
  for (const auto& chart : c.charts) {
    if (chart.file.rfind("fig1_", 0) == 0 || chart.file.rfind("gci_", 0) == 0) continue;
    out += "### " + chart.chart.title + "\n\n" + chart_link(chart);
  }
  out += "### Per series\n\n";
  if (summary) {
    out += "Each series' charts and rows are on its page, series/<series>.html (linked from report.html's series "
           "table), its chart files beside it in series/.\n\n";
  } else {
    for (const auto& chart : c.charts) {
      if (chart.file.rfind("fig1_", 0) == 0 || chart.file.rfind("gci_", 0) == 0) out += chart_link(chart);
    }
  }
  if (!c.alignment.empty()) out += table_section(c.alignment_table, "", cap);
  out += table_section(c.gci_table, "No series has three converged grids yet.", cap);
  out += stability_section_markdown(c);  // "Where methods fail" (stability_section.h)
  out += table_section(c.failures_table, "None: every finished grid converged.", cap);
  out += table_section(c.grids_table, "No grids.", cap);
  return out;
}

}  // namespace gridfree
