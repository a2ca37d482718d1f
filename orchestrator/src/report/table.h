// SPDX-License-Identifier: GPL-3.0-or-later
// A report table and its three renderings: CSV (full precision, every
// column), Markdown and HTML (rounded values, display columns only).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gridfree {

struct Cell {
  std::string exact;   // CSV text
  std::string shown;   // Markdown/HTML text
  std::string href = {};  // HTML: the shown text links here (empty: no link)
};

struct Column {
  std::string name;          // CSV header
  std::string title;         // displayed header (defaults to name)
  bool csv_only = false;     // left out of the Markdown/HTML table
  bool numeric = false;      // right-aligned in HTML
  bool prose = false;        // free text (notes, reasons): wraps in HTML
  bool screen_only = false;  // HTML on screen, left out in print (a detail whose values the CSV keeps),
                             // so the printed table fits a portrait page (table_print_fit.h)
};

struct Table {
  std::vector<Column> columns;
  std::vector<std::vector<Cell>> rows;   // one Cell per column
};

// Cells from text and numbers; a missing number is an empty cell.
Cell text_cell(std::string value);
Cell number_cell(const std::optional<double>& value, int shown_digits = 6);
Cell percent_cell(const std::optional<double>& fraction, int shown_digits = 3);
Cell integer_cell(long long value);
// A value shown to the decimal place `u` supports (extrap/value_format.h),
// so a column of values of one U keeps its trailing zeros ("1021.0000"
// beside "1021.0002", not "1021").
Cell value_cell(const std::optional<double>& value, const std::optional<double>& u);

// `with_header` false: the rows alone (a table written in parts).
std::string to_csv(const Table& table, bool with_header = true);

// The same columns with the first n rows.
Table first_rows(const Table& table, std::size_t n);
// Row indices grouped by the exact (CSV) text of column `column`; empty
// when the table has no such column.
std::map<std::string, std::vector<std::size_t>> rows_by(const Table& table, const std::string& column);
// The same columns with the given rows, in the given order.
Table rows_at(const Table& table, const std::vector<std::size_t>& rows);
// Markdown and HTML show a numeric column in one notation: when one of its
// plain numbers is in exponent form, all are (same significant digits).
std::string to_markdown(const Table& table);
// <table class="... fit-..."> with <thead>/<tbody>; cells' classes carry
// alignment, the fit-... class the table's print layout (table_print_fit.h).
std::string to_html(const Table& table, const std::string& css_class = "data");

}  // namespace gridfree
