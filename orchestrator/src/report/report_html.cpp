// SPDX-License-Identifier: GPL-3.0-or-later
// report.html: one self-contained page (inline CSS, inline SVG charts, no
// external resources), with the same content as report.md. Full page: every
// series on it, no scripts. Summary layout (report_layout.h): the study's
// overview, each series on its page (series_page.cpp), and one small inline
// script, the series table's filter (the page reads without it).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "report/adaptive_section.h"
#include "report/first_screen.h"
#include "report/series_filter.h"
#include "report/html_blocks.h"
#include "report/html_toc.h"
#include "report/report_about.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/series_coverage.h"
#include "report/stability_section.h"
#include "report/text_format.h"
#include "report/verdict_counts.h"

namespace gridfree {

namespace {


std::string verdict_section(const ReportContent& c) {
  std::string out = "<h2 id=\"verdicts\">Verdicts</h2>\n<p class=\"note\">" +
                    xml_escape(reading_note("verdicts")) + "</p>\n";
  for (const auto& v : verdict_items(c)) out += verdict_block(v);
  return out;
}

// Summary layout (report_layout.h): the counts per factor level; the ranked
// series are the first screen's attention list.
std::string verdict_summary(const ReportContent& c) {
  std::string out = "<h2 id=\"verdicts\">Verdicts</h2>\n<p class=\"note\">" +
                    xml_escape(reading_note("verdicts")) + "</p>\n";
  out += "<div class=\"scroll\">\n" + to_html(c.verdict_count_table.table) + "</div>\n";
  out += "<p class=\"note\">CSV: <a href=\"" + xml_escape(c.verdict_count_table.file) + "\">" +
         xml_escape(c.verdict_count_table.file) + "</a></p>\n";
  // Which series need a look, ranked, is the attention list at the top
  // (first_screen.h): no second list of verdict blocks here.
  out += "<p class=\"note\">The series that need a look, worst first, are <a href=\"#attention\">under "
         "Attention</a> at the top; every series' verdict is in <a href=\"#series\">the series table</a> and on its "
         "own page.</p>\n";
  return out;
}

// The series table of the summary layout: every row, each series linked to
// its page, with a filter of exact tokens (series_filter.h): whole words of
// the row, `field:value`, `field>number`.
std::string filtered_series_table(const ReportContent& c) {
  std::string out = table_section(c.series_table, "series", "No series.");
  const std::string filter =
      "<p class=\"filter\"><label>Filter series: <input type=\"search\" id=\"series-filter\" "
      "placeholder=\"e.g. verdict:pre-asymptotic failed>0 hkl\"></label> <span id=\"series-shown\"></span></p>\n"
      "<p class=\"note filter-help\">" + xml_escape(series_filter_help(c.series_table.table)) + "</p>\n" +
      series_filter_script(c.series_table.table);
  // The filter above the table, the script after it (the rows exist when it runs).
  const std::string scroll = "<div class=\"scroll\">";
  const auto table_at = out.find(scroll);
  if (table_at == std::string::npos) return out;  // no series: nothing to filter
  out.replace(table_at, scroll.size(), filter.substr(0, filter.find("<script>")) +
                                           "<div class=\"scroll\" id=\"series-rows\">");
  const std::string div_end = "</div>\n";
  const auto table_end = out.find(div_end, out.find("</table>", table_at));
  out.insert(table_end + div_end.size(), filter.substr(filter.find("<script>")));
  return out;
}

std::string about_section(const ReportContent& c) {
  std::string out;
  int n = 0;
  for (const auto& a : study_about_sections(c)) {
    out += "<h2 id=\"about" + (n++ ? "-" + std::to_string(n) : std::string()) + "\">" + xml_escape(a.title) + "</h2>\n";
    for (const auto& p : a.paragraphs) out += "<p>" + xml_escape(p) + "</p>\n";
  }
  return out;
}

// Every section of `body` (html_toc.h) and every file beside the report, linked.
std::string contents(const ReportContent& c, const std::string& body) {
  // Two blocks that a column break never splits (a heading stays with its list).
  std::string out = "<nav class=\"toc\"><div><strong>Contents</strong>\n" + toc_list_html(html_sections(body));
  out += "</div><div><strong>Files</strong>\n<ul>\n";
  for (const NamedTable* t :
       {&c.series_table, &c.verdict_count_table, &c.differences_table, &c.cost_table, &c.coverage_table,
        &c.gci_table, &c.failures_table, &c.grids_table})
    out += "<li><a href=\"" + xml_escape(t->file) + "\">" + xml_escape(t->file) + "</a></li>\n";
  for (const char* f : {kStabilityCsv, kStabilitySeriesCsv, kStabilitySvg})
    out += "<li><a href=\"" + std::string(f) + "\">" + f + "</a></li>\n";
  for (const auto& chart : c.charts) {
    out += "<li><a href=\"" + xml_escape(chart.file) + "\">" + xml_escape(chart.file) + "</a>";
    for (const auto& extra : chart.converted)
      out += " · <a href=\"" + xml_escape(extra) + "\">" + xml_escape(extra.substr(extra.rfind('.') + 1)) + "</a>";
    out += "</li>\n";
  }
  out += "</ul>";
  if (!c.export_note.empty()) out += "<p class=\"note\">" + xml_escape(c.export_note) + "</p>";
  out += "</div></nav>\n";
  return out;
}

bool per_series(const NamedChart& c) { return c.file.rfind("fig1_", 0) == 0 || c.file.rfind("gci_", 0) == 0; }

std::string full_page_body(const ReportContent& c) {
  std::string body = verdict_section(c);
  body += adaptive_section_html(c.data.adaptive_decisions);
  body += about_section(c);
  body += ensembles_html(c);
  body += table_section(c.series_table, "series", "No series.");
  body += table_section(c.differences_table, "differences", "No two series differ in exactly one factor.");
  body += table_section(c.cost_table, "cost", "No series has an extrapolation yet.");
  body += table_section(c.coverage_table, "coverage",
                        "No series checked: " + coverage_not_made(c.series) + ".");
  body += "<h2 id=\"charts\">Charts</h2>\n<div class=\"charts\">\n";
  for (const auto& chart : c.charts) {
    if (!per_series(chart)) body += figure(chart);
  }
  body += "</div>\n<h3 id=\"per-series\">Per series</h3>\n<div class=\"charts\">\n";
  for (const auto& chart : c.charts) {
    if (per_series(chart)) body += figure(chart);
  }
  body += "</div>\n";
  if (!c.alignment.empty()) body += table_section(c.alignment_table, "alignment", "");
  body += table_section(c.gci_table, "gci", "No series has three converged grids yet.");
  body += stability_section_html(c);  // "Where methods fail" (stability_section.h)
  body += table_section(c.failures_table, "failures", "None: every finished grid converged.");
  body += table_section(c.grids_table, "grids", "No grids.");
  return body;
}

// report_layout.h: too many series for one page; long tables cut to their
// first rows, each series' charts and rows on its own page.
std::string summary_body(const ReportContent& c) {
  std::string body = verdict_summary(c);
  body += adaptive_section_html(c.data.adaptive_decisions);
  body += about_section(c);
  body += ensembles_html(c);
  body += filtered_series_table(c);
  body += table_section(c.differences_table, "differences", "No two series differ in exactly one factor.", kShownRows);
  body += table_section(c.cost_table, "cost", "No series has an extrapolation yet.", kShownRows);
  body += table_section(c.coverage_table, "coverage",
                        "No series checked: " + coverage_not_made(c.series) + ".",
                        kShownRows);
  body += "<h2 id=\"charts\">Charts</h2>\n<p class=\"note\">With " + std::to_string(c.series.size()) +
          " series the study charts aggregate (RDE: median and 10–90 % band per factor level) or sample "
          "(speed-accuracy: the series drawn are named in each chart's note); every series' own charts are on "
          "its page, linked from the series table.</p>\n<div class=\"charts\">\n";
  for (const auto& chart : c.charts) body += figure(chart);
  body += "</div>\n";
  if (!c.alignment.empty()) body += table_section(c.alignment_table, "alignment", "", kShownRows);
  body += table_section(c.gci_table, "gci", "No series has three converged grids yet.", kShownRows);
  body += stability_section_html(c);  // "Where methods fail" (stability_section.h): failures first, rows capped
  body += table_section(c.failures_table, "failures", "None: every finished grid converged.", kShownRows);
  body += table_section(c.grids_table, "grids", "No grids.", kShownRows);
  return body;
}

}  // namespace

std::string render_html(const ReportContent& c) {
  const std::string title = "Grid-convergence report: " + c.data.study_name;
  std::string out = html_page_head(title);
  // The answer first (first_screen.h), then the study's particulars.
  out += "<h1>" + xml_escape(title) + "</h1>\n" + first_screen_html(c) + "<dl class=\"summary\">\n";
  for (const auto& [key, value] : summary_items(c)) {
    out += "<dt>" + xml_escape(key) + "</dt><dd>" + xml_escape(value) + "</dd>\n";
  }
  out += "</dl>\n";
  const std::string body = c.layout == ReportLayout::summary ? summary_body(c) : full_page_body(c);
  out += contents(c, body) + body;
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace gridfree
