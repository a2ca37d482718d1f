// SPDX-License-Identifier: GPL-3.0-or-later
// The series table's filter on the summary page (docs/REPORTS.md "Filter"):
// every token of the query must hold for a row to show.
//   word            a whole word of any field of the row (fields split at
//                   white space, commas, semicolons and parentheses; "12"
//                   does not match "inst12" or "1012.x")
//   field:value     the field (a series.csv column) equals value, or has it
//                   as a whole word: verdict:pre-asymptotic, drag:gidaspow
//                   (not gidaspow_blend), attention:yes
//   field>number    also <, >=, <=, =: numeric comparison (failed>0)
// Case-insensitive. An unknown field shows no row and names the fields. The
// rows' fields (CSV text of the series table, without its long prose
// columns) are embedded in the script, so CSV-only columns (factors,
// attention) filter too.
#pragma once

#include <string>
#include <vector>

#include "report/table.h"

namespace gridfree {

// The columns the filter knows, by CSV name, in table order.
std::vector<std::string> series_filter_fields(const Table& series_table);

// One line saying how to filter, with the field names.
std::string series_filter_help(const Table& series_table);

// <script>…</script>: the rows' fields and the matching above, bound to the
// input #series-filter, the rows of #series-rows and links with data-filter.
std::string series_filter_script(const Table& series_table);

}  // namespace gridfree
