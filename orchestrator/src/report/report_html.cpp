// report.html: one self-contained page (inline CSS, inline SVG charts, no
// scripts, no external resources), with the same content as report.md.
#include <string>
#include <utility>
#include <vector>

#include "report/adaptive_section.h"
#include "report/html_toc.h"
#include "report/report_about.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 2em auto; max-width: 1400px; padding: 0 1em; color: #222; box-sizing: border-box; }
h1 { font-size: 1.6em; } h2 { margin-top: 2em; border-bottom: 1px solid #ccc; } h3 { font-size: 1.05em; }
dl.summary { display: grid; grid-template-columns: max-content auto; gap: 0.2em 1em; }
dl.summary dt { font-weight: bold; } dl.summary dd { margin: 0; }
nav.toc { columns: 2; font-size: 0.9em; } nav.toc ul { margin: 0.2em 0; } nav.toc > div { break-inside: avoid; }
nav.toc a { overflow-wrap: anywhere; }
@media (max-width: 700px) { nav.toc { columns: 1; } }
.attention { background: #fff4e5; border-left: 4px solid #e69f00; padding: 0.5em 1em; }
.scroll { overflow-x: auto; }
table.data { border-collapse: collapse; font-size: 0.85em; margin: 0.5em 0; }
table.data th, table.data td { border: 1px solid #ccc; padding: 0.2em 0.5em; white-space: nowrap; }
table.data td.prose { white-space: normal; min-width: 18em; max-width: 36em; }
table.data th { background: #f2f2f2; } table.data td.num { text-align: right; font-variant-numeric: tabular-nums; }
table.data tr:nth-child(even) td { background: #fafafa; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(min(620px, 100%), 1fr)); gap: 0 1.5em; }
figure { margin: 1em 0; } figure svg { max-width: 100%; height: auto; }
figcaption { font-size: 0.9em; color: #444; max-width: 720px; }
p.note { font-size: 0.9em; color: #444; max-width: 900px; }
div.verdict { border-left: 4px solid #999; padding: 0 1em; margin: 0.5em 0; }
div.verdict-converged { border-color: #009e73; } div.verdict-pre-asymptotic { border-color: #e69f00; }
div.verdict-unreliable, div.verdict-insufficient_grids { border-color: #d55e00; }
div.verdict .word { font-weight: bold; } div.verdict ul { margin: 0.2em 0 0.5em; }
@page { size: A4; margin: 10mm; }
@page landscape { size: A4 landscape; margin: 10mm; }
@media print {
  body { max-width: none; margin: 0; padding: 0; font-size: 9pt; }
  .scroll { overflow: visible; }
  table.data { font-size: 6.5pt; table-layout: auto; }
  table.data.fit-landscape-small { font-size: 5pt; }
  section:has(> .scroll > table.fit-landscape, > .scroll > table.fit-landscape-small),
  .scroll:has(> table.fit-landscape, > table.fit-landscape-small) { page: landscape; }
  table.data th, table.data td { white-space: normal; overflow-wrap: normal; word-break: normal; padding: 1px 2px; }
  table.data td.num { white-space: nowrap; } table.data.fit-landscape-small td.num { white-space: normal; }
  table.data td.prose { min-width: 10em; }
  .charts { display: block; }
  figure { break-inside: avoid; } h2, h3 { break-after: avoid; }
  nav.toc { columns: 1; }
}
)css";

// A table under its heading, in a <section> so that a table printed on a
// landscape page takes its heading and notes along.
std::string table_section(const NamedTable& t, const std::string& id, const std::string& empty_text) {
  std::string out = "<section>\n<h2 id=\"" + id + "\">" + xml_escape(t.title) + "</h2>\n";
  const std::string note = reading_note(t.file);
  if (!note.empty()) out += "<p class=\"note\">" + xml_escape(note) + "</p>\n";
  out += t.table.rows.empty() ? "<p>" + xml_escape(empty_text) + "</p>\n"
                              : "<div class=\"scroll\">\n" + to_html(t.table) + "</div>\n";
  out += "<p class=\"note\">CSV: " + xml_escape(t.file) + " (beside this file)</p>\n</section>\n";
  return out;
}

std::string figure(const NamedChart& c) {
  return "<figure id=\"" + xml_escape(slugify(c.file)) + "\">\n" + render_svg(c.chart) + "<figcaption>" +
         xml_escape(c.caption) + " File: " + xml_escape(c.file) + "</figcaption>\n</figure>\n";
}

std::string verdict_section(const ReportContent& c) {
  std::string out = "<h2 id=\"verdicts\">Verdicts</h2>\n<p class=\"note\">" +
                    xml_escape(reading_note("verdicts")) + "</p>\n";
  for (const auto& v : verdict_items(c)) {
    out += "<div class=\"verdict verdict-" + xml_escape(v.verdict) + "\"><p><strong>" + xml_escape(v.label) +
           "</strong>: <span class=\"word\">" + xml_escape(v.verdict) + "</span> — " + xml_escape(v.headline) +
           "</p>\n<ul>\n";
    for (const auto& r : v.reasons) out += "<li>" + xml_escape(r) + "</li>\n";
    for (const auto& n : v.notes) out += "<li class=\"extra\">Note: " + xml_escape(n) + "</li>\n";
    out += "</ul></div>\n";
  }
  return out;
}

std::string about_section(const ReportContent& c) {
  std::string out;
  int n = 0;
  for (const auto& a : about_sections(c.data.generator_kinds)) {
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
       {&c.series_table, &c.differences_table, &c.cost_table, &c.coverage_table, &c.gci_table, &c.failures_table,
        &c.grids_table})
    out += "<li><a href=\"" + xml_escape(t->file) + "\">" + xml_escape(t->file) + "</a></li>\n";
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

}  // namespace

std::string render_html(const ReportContent& c) {
  const std::string title = "Grid-convergence report: " + c.data.study_name;
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + xml_escape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
  out += "<h1>" + xml_escape(title) + "</h1>\n<dl class=\"summary\">\n";
  for (const auto& [key, value] : summary_items(c)) {
    out += "<dt>" + xml_escape(key) + "</dt><dd>" + xml_escape(value) + "</dd>\n";
  }
  out += "</dl>\n";
  const auto warnings = series_warnings(c);
  if (!warnings.empty()) {
    out += "<div class=\"attention\"><strong>Attention:</strong><ul>\n";
    for (const auto& w : warnings) out += "<li>" + xml_escape(w) + "</li>\n";
    out += "</ul></div>\n";
  }
  std::string body = verdict_section(c);
  body += adaptive_section_html(c.data.adaptive_decisions);
  body += about_section(c);
  body += ensembles_html(c);
  body += table_section(c.series_table, "series", "No series.");
  body += table_section(c.differences_table, "differences", "No two series differ in exactly one factor.");
  body += table_section(c.cost_table, "cost", "No series has an extrapolation yet.");
  body += table_section(c.coverage_table, "coverage",
                        "No series checked yet: a series needs all its grids and at least 6 of them converged.");
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
  body += table_section(c.failures_table, "failures", "None: every finished grid converged.");
  body += table_section(c.grids_table, "grids", "No grids.");
  out += contents(c, body) + body;
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace gridfree
