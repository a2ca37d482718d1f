// SPDX-License-Identifier: GPL-3.0-or-later
// One series' page (see series_page.h).
#include "report/series_page.h"

#include "report/html_blocks.h"
#include "report/report_summary.h"
#include "report/report_tables.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

// The series' rows of a study table, the CSV linked in the study folder.
std::string rows_section(const NamedTable& t, const std::map<std::string, std::vector<std::size_t>>& index,
                         const std::string& label, const std::string& id, const std::string& empty_text) {
  const auto it = index.find(label);
  NamedTable mine{t.file, t.title, rows_at(t.table, it == index.end() ? std::vector<std::size_t>{} : it->second)};
  for (auto& row : mine.table.rows)
    for (auto& cell : row) cell.href.clear();  // links of the study page, not of this one
  return table_section(mine, id, empty_text, kShownRows * 4, "../" + t.file);
}

}  // namespace

SeriesRowIndex series_row_index(const ReportContent& c) {
  return {rows_by(c.series_table.table, "series"), rows_by(c.coverage_table.table, "series"),
          rows_by(c.failures_table.table, "series")};
}

std::string render_series_page(const ReportContent& c, const SeriesRowIndex& rows, std::size_t index,
                               const std::vector<NamedChart>& charts, const std::vector<std::string>& svgs) {
  const SeriesSummary& s = c.series[index];
  const std::string title = s.label + " — " + c.data.study_name;
  std::string out = html_page_head(title);
  out += "<p><a href=\"../report.html\">← study report: " + xml_escape(c.data.study_name) + "</a> · series " +
         std::to_string(index + 1) + " of " + std::to_string(c.series.size()) + "</p>\n";
  out += "<h1>" + xml_escape(s.label) + "</h1>\n";
  out += "<h2 id=\"verdict\">Verdict</h2>\n<p class=\"note\">" + xml_escape(reading_note("verdicts")) + "</p>\n";
  out += verdict_block(verdict_item(s));
  out += rows_section(c.series_table, rows.series, s.label, "series", "No extrapolation.");
  out += "<h2 id=\"charts\">Charts</h2>\n<div class=\"charts\">\n";
  for (std::size_t k = 0; k < charts.size(); ++k) out += figure(charts[k], {}, k < svgs.size() ? svgs[k] : std::string());
  out += "</div>\n";
  out += rows_section(c.coverage_table, rows.coverage, s.label, "coverage",
                      "Not checked: a series needs all its grids and at least 6 of them converged.");
  out += table_section({c.grids_table.file, c.grids_table.title, grids_table({s}), 0}, "grids", "No grids.",
                       kShownRows * 4, "../" + c.grids_table.file);
  out += table_section({c.gci_table.file, c.gci_table.title, gci_table({s}, c.data.p_low, c.data.p_high), 0}, "gci", "No three converged grids.",
                       kShownRows * 4, "../" + c.gci_table.file);
  out += rows_section(c.failures_table, rows.failures, s.label, "failures", "None: every finished grid converged.");
  out += "</body>\n</html>\n";
  return out;
}

}  // namespace gridfree
