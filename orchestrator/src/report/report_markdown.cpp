// SPDX-License-Identifier: GPL-3.0-or-later
// report.md: summary, tables, and links to the SVG charts beside it.
#include <algorithm>
#include <limits>
#include <string>

#include "report/adaptive_section.h"
#include "report/report_about.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/report_layout.h"
#include "report/series_concerns.h"
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

// The series that need a look with their verdicts, ranked as the Attention
// list ranks them (series_concerns.h: failed or stalled grids, a missed
// coverage self-check, a verdict other than converged, an order against the
// declared one), the first kWorstSeries and "… and N more".
std::string needs_a_look_markdown(const ReportContent& c) {
  const auto concerns = series_concerns(c.series, c.data.p_low, c.data.p_high);
  std::string out = "### Series that need a look, worst first\n\n";
  if (concerns.empty()) return out + "None: every series is converged on all its grids.\n";
  const std::size_t shown = std::min(concerns.size(), kWorstSeries);
  for (std::size_t k = 0; k < shown; ++k) {
    const std::size_t i = concerns[k].series;
    VerdictItem item = verdict_item(c.series[i]);
    std::string why;
    for (const auto& t : concerns[k].concerns) why += (why.empty() ? "" : "; ") + t;
    item.notes.insert(item.notes.begin(), "Needs a look: " + why);
    verdict_lines(out, item, series_page_file(c, i));
  }
  if (concerns.size() > shown)
    out += "- … and " + std::to_string(concerns.size() - shown) + " more of " + std::to_string(concerns.size()) +
           " (series.csv: `attention` = yes, `concerns` says why; each series' page)\n";
  return out;
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
           c.verdict_count_table.file + ")\n\n";
    out += needs_a_look_markdown(c);
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
