// SPDX-License-Identifier: GPL-3.0-or-later
// series/<slug>.html, one series' page in a report of the summary layout
// (report_layout.h): its verdict, its charts inline (Fig. 1 and the GCI
// chart), and its rows of the series, coverage, grids, GCI and failures
// tables, with a link back to the study page. Self-contained like the
// study page; its chart files lie beside it in series/.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "report/report_content.h"

namespace gridfree {

// The series, coverage and failures tables' rows by series label, made once
// per report write so a page takes its rows without scanning the tables
// (the grids and GCI rows a page makes itself: the summary layout does not
// hold those tables whole, report_content.h).
struct SeriesRowIndex {
  std::map<std::string, std::vector<std::size_t>> series, coverage, failures;
};
SeriesRowIndex series_row_index(const ReportContent& content);

// `svgs`: each chart rendered (render_svg), in the charts' order.
std::string render_series_page(const ReportContent& content, const SeriesRowIndex& rows, std::size_t index,
                               const std::vector<NamedChart>& charts, const std::vector<std::string>& svgs);

}  // namespace gridfree
