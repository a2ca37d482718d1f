// SPDX-License-Identifier: GPL-3.0-or-later
// Shared HTML pieces of the report pages (see html_blocks.h).
#include "report/html_blocks.h"

#include <algorithm>

#include "report/html_style.h"
#include "report/text_format.h"

namespace gridfree {

std::string html_page_head(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         xml_escape(title) + "</title>\n<style>" + report_css() + "</style>\n</head>\n<body>\n";
}

std::string table_section(const NamedTable& t, const std::string& id, const std::string& empty_text,
                          std::size_t max_rows, const std::string& csv_href) {
  std::string out = "<section>\n<h2 id=\"" + id + "\">" + xml_escape(t.title) + "</h2>\n";
  const std::string note = reading_note(t.file, t.words);
  if (!note.empty()) out += "<p class=\"note\">" + xml_escape(note) + "</p>\n";
  const bool cut = t.rows() > std::min(max_rows, t.table.rows.size());
  out += t.table.rows.empty() ? "<p>" + xml_escape(empty_text) + "</p>\n"
                              : "<div class=\"scroll\">\n" + to_html(cut ? first_rows(t.table, max_rows) : t.table) +
                                    "</div>\n";
  const std::string href = csv_href.empty() ? t.file : csv_href;
  out += "<p class=\"note\">";
  if (cut)
    out += "The first " + std::to_string(std::min(max_rows, t.table.rows.size())) + " of " + std::to_string(t.rows()) +
           " rows; every row in ";
  else
    out += "CSV: ";
  out += "<a href=\"" + xml_escape(href) + "\">" + xml_escape(t.file) + "</a>" +
         (csv_href.empty() ? " (beside this file)" : "") + "</p>\n</section>\n";
  return out;
}

std::string figure(const NamedChart& c, const std::string& file_href, const std::string& svg) {
  const std::string href = file_href.empty() ? c.file : file_href;
  // Both renderings: the wide one for screens and print, the narrow one for
  // phones (report_css: which one shows follows the page width).
  return "<figure id=\"" + xml_escape(slugify(c.file)) + "\">\n<div class=\"chart-wide\">" +
         (svg.empty() ? render_svg(c.chart) : svg) + "</div><div class=\"chart-narrow\">" +
         render_svg(narrow_chart(c.chart)) + "</div>" +
         "<figcaption>" +
         xml_escape(c.caption) + " File: <a href=\"" + xml_escape(href) + "\">" + xml_escape(c.file) +
         "</a></figcaption>\n</figure>\n";
}

std::string verdict_block(const VerdictItem& v, const std::string& href) {
  const std::string label = href.empty() ? xml_escape(v.label)
                                         : "<a href=\"" + xml_escape(href) + "\">" + xml_escape(v.label) + "</a>";
  std::string out = "<div class=\"verdict verdict-" + xml_escape(v.verdict) + "\" id=\"v-" +
                    xml_escape(slugify(v.label)) + "\"><p><strong>" + label +
                    "</strong>: <span class=\"word\">" + xml_escape(v.verdict) + "</span> — " +
                    xml_escape(v.headline) + "</p>\n<ul>\n";
  for (const auto& r : v.reasons) out += "<li>" + xml_escape(r) + "</li>\n";
  for (const auto& n : v.notes) out += "<li class=\"extra\">Note: " + xml_escape(n) + "</li>\n";
  out += "</ul></div>\n";
  return out;
}

}  // namespace gridfree
