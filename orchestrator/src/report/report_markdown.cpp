// report.md: summary, tables, and links to the SVG charts beside it.
#include <string>

#include "report/adaptive_section.h"
#include "report/report_about.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

std::string table_section(const NamedTable& t, const std::string& empty_text) {
  std::string out = "## " + t.title + "\n\n";
  const std::string note = reading_note(t.file);
  if (!note.empty()) out += note + "\n\n";
  out += t.table.rows.empty() ? empty_text + "\n" : to_markdown(t.table);
  out += "\nCSV: [" + t.file + "](" + t.file + ")\n\n";
  return out;
}

std::string chart_link(const NamedChart& c) {
  return "![" + md_cell(c.chart.title) + "](" + c.file + ")\n\n" + c.caption + "\n\n";
}

}  // namespace

std::string render_markdown(const ReportContent& c) {
  std::string out = "# Grid-convergence report: " + c.data.study_name + "\n\n";
  for (const auto& [key, value] : summary_items(c)) out += "- **" + key + ":** " + value + "\n";
  out += "\n";
  const auto warnings = series_warnings(c);
  if (!warnings.empty()) {
    out += "**Attention:**\n\n";
    for (const auto& w : warnings) out += "- " + w + "\n";
    out += "\n";
  }
  out += "## Verdicts\n\n" + reading_note("verdicts") + "\n\n";
  for (const auto& v : verdict_items(c)) {
    out += "- **" + v.label + "**: **" + v.verdict + "** — " + v.headline + "\n";
    for (const auto& r : v.reasons) out += "  - " + r + "\n";
    for (const auto& n : v.notes) out += "  - Note: " + n + "\n";
  }
  out += "\n";
  out += adaptive_section_markdown(c.data.adaptive_decisions);
  for (const auto& a : about_sections(c.data.generator_kinds)) {
    out += "## " + a.title + "\n\n";
    for (const auto& p : a.paragraphs) out += p + "\n\n";
  }
  out += ensembles_markdown(c);
  out += table_section(c.series_table, "No series.");
  out += table_section(c.differences_table, "No two series differ in exactly one factor.");
  out += table_section(c.cost_table, "No series has an extrapolation yet.");
  out += table_section(c.coverage_table,
                       "No series checked yet: a series needs all its grids and at least 6 of them converged.");
  out += "## Charts\n\n";
  if (!c.export_note.empty()) out += c.export_note + "\n\n";
  for (const auto& chart : c.charts) {
    if (chart.file.rfind("fig1_", 0) == 0 || chart.file.rfind("gci_", 0) == 0) continue;
    out += "### " + chart.chart.title + "\n\n" + chart_link(chart);
  }
  out += "### Per series\n\n";
  for (const auto& chart : c.charts) {
    if (chart.file.rfind("fig1_", 0) == 0 || chart.file.rfind("gci_", 0) == 0) out += chart_link(chart);
  }
  if (!c.alignment.empty()) out += table_section(c.alignment_table, "");
  out += table_section(c.gci_table, "No series has three converged grids yet.");
  out += table_section(c.failures_table, "None: every finished grid converged.");
  out += table_section(c.grids_table, "No grids.");
  return out;
}

}  // namespace gridfree
