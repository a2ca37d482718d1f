// SPDX-License-Identifier: GPL-3.0-or-later
// Pieces of HTML shared by the study page (report_html.cpp) and the series
// pages (series_page.cpp). Text arguments are plain text: escaped here.
#pragma once

#include <cstddef>
#include <limits>
#include <string>

#include "report/report_charts.h"
#include "report/report_content.h"
#include "report/report_summary.h"

namespace gridfree {

// <!DOCTYPE html> … <body>\n with the title and the inline style sheet.
std::string html_page_head(const std::string& title);

// A table under its heading, in a <section> so that a table printed on a
// landscape page takes its heading and notes along. At most `max_rows`
// rows; a longer table says how many rows the page shows and that every
// row is in its CSV. `csv_href`: the CSV's address from this page.
std::string table_section(const NamedTable& t, const std::string& id, const std::string& empty_text,
                          std::size_t max_rows = std::numeric_limits<std::size_t>::max(),
                          const std::string& csv_href = {});

// A chart inline with its caption; `file_href`: the SVG file's address;
// `svg`: the chart already rendered (render_svg), empty: rendered here.
std::string figure(const NamedChart& c, const std::string& file_href = {}, const std::string& svg = {});

// One series' verdict: label (a link when `href` is given), word, headline,
// reasons and notes.
std::string verdict_block(const VerdictItem& v, const std::string& href = {});

}  // namespace gridfree
