// SPDX-License-Identifier: GPL-3.0-or-later
// CSV, Markdown and HTML renderings of a Table (see table.h).
#include "report/table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "extrap/value_format.h"
#include "report/table_print_fit.h"
#include "report/text_format.h"

namespace gridfree {

Cell text_cell(std::string value) { return {value, value}; }

Cell number_cell(const std::optional<double>& value, int shown_digits) {
  return {format_exact(value), format_g(value, shown_digits)};
}

Cell percent_cell(const std::optional<double>& fraction, int shown_digits) {
  return {format_exact(fraction), format_percent(fraction, shown_digits)};
}

Cell integer_cell(long long value) { return text_cell(std::to_string(value)); }

Cell value_cell(const std::optional<double>& value, const std::optional<double>& u) {
  return {format_exact(value), value ? format_value_for_u(*value, u, 8) : std::string()};
}

namespace {

std::string title_of(const Column& c) { return c.title.empty() ? c.name : c.title; }

// A shown cell that is one finite number and nothing else ("1.2e-05", "8").
bool plain_number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && std::isfinite(v);
}

bool in_exponent_form(const std::string& s) {
  double v = 0;
  return plain_number(s, v) && s.find_first_of("eE") != std::string::npos;
}

// Significant digits a fixed-notation number shows ("0.000109" → 3, "1000" → 4).
int significant_digits(const std::string& s) {
  int n = 0;
  bool leading = true;
  for (char ch : s) {
    if (ch < '0' || ch > '9') continue;
    if (leading && ch == '0') continue;
    leading = false;
    ++n;
  }
  return std::max(1, n);
}

// Numeric columns with a cell in exponent notation: every plain number of
// such a column is shown in it too, with the digits it had (no column mixes
// "0.000109" and "9.38e-06"). Cells with more than a number ("1017.0 ± 1.5",
// "12%") are left as they are.
std::vector<bool> exponent_columns(const Table& t) {
  std::vector<bool> out(t.columns.size(), false);
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    if (!t.columns[i].numeric || t.columns[i].csv_only) continue;
    for (const auto& row : t.rows)
      if (i < row.size() && in_exponent_form(row[i].shown)) {
        out[i] = true;
        break;
      }
  }
  return out;
}

std::string shown_text(const std::vector<bool>& exponent, std::size_t i, const std::vector<Cell>& row) {
  if (i >= row.size()) return {};
  const std::string& s = row[i].shown;
  double v = 0;
  if (!exponent[i] || !plain_number(s, v) || in_exponent_form(s)) return s;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*e", significant_digits(s) - 1, v);
  return buf;
}

}  // namespace

std::string to_csv(const Table& table, bool with_header) {
  std::string out;
  for (std::size_t i = 0; with_header && i < table.columns.size(); ++i) {
    if (i) out += ',';
    out += csv_field(table.columns[i].name);
  }
  if (with_header) out += "\n";
  for (const auto& row : table.rows) {
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      if (i) out += ',';
      out += csv_field(i < row.size() ? row[i].exact : std::string());
    }
    out += "\n";
  }
  return out;
}

std::string to_markdown(const Table& table) {
  std::string head = "|", rule = "|";
  for (const auto& c : table.columns) {
    if (c.csv_only) continue;
    head += ' ';
    head += md_cell(title_of(c));
    head += " |";
    rule += c.numeric ? " ---: |" : " --- |";
  }
  std::string out = head + "\n" + rule + "\n";
  const auto exponent = exponent_columns(table);
  for (const auto& row : table.rows) {
    out += "|";
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      if (table.columns[i].csv_only) continue;
      out += ' ';
      out += md_cell(shown_text(exponent, i, row));
      out += " |";
    }
    out += "\n";
  }
  return out;
}

Table first_rows(const Table& table, std::size_t n) {
  Table out{table.columns, {}};
  out.rows.assign(table.rows.begin(), table.rows.begin() + static_cast<std::ptrdiff_t>(std::min(n, table.rows.size())));
  return out;
}

std::map<std::string, std::vector<std::size_t>> rows_by(const Table& table, const std::string& column) {
  std::map<std::string, std::vector<std::size_t>> out;
  std::size_t k = 0;
  while (k < table.columns.size() && table.columns[k].name != column) ++k;
  if (k == table.columns.size()) return out;
  for (std::size_t i = 0; i < table.rows.size(); ++i)
    if (k < table.rows[i].size()) out[table.rows[i][k].exact].push_back(i);
  return out;
}

Table rows_at(const Table& table, const std::vector<std::size_t>& rows) {
  Table out{table.columns, {}};
  out.rows.reserve(rows.size());
  for (std::size_t i : rows) out.rows.push_back(table.rows.at(i));
  return out;
}

std::string to_html(const Table& table, const std::string& css_class) {
  // The print layout class (table_print_fit.h) rides along with the caller's.
  std::string out = "<table class=\"" + xml_escape(css_class) + " " + print_fit_class(table) + "\">\n<thead><tr>";
  for (const auto& c : table.columns) {
    if (!c.csv_only) out += (c.screen_only ? "<th class=\"screen-only\">" : "<th>") + xml_escape(title_of(c)) + "</th>";
  }
  out += "</tr></thead>\n<tbody>\n";
  const auto exponent = exponent_columns(table);
  for (const auto& row : table.rows) {
    out += "<tr>";
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
      const Column& c = table.columns[i];
      if (c.csv_only) continue;
      const std::string cls = std::string(c.numeric ? "num" : c.prose ? "prose" : "") +
                              (c.screen_only ? (c.numeric || c.prose ? " screen-only" : "screen-only") : "");
      out += cls.empty() ? "<td>" : "<td class=\"" + cls + "\">";
      const std::string shown = xml_escape(shown_text(exponent, i, row));
      out += (i < row.size() && !row[i].href.empty() ? "<a href=\"" + xml_escape(row[i].href) + "\">" + shown + "</a>"
                                                    : shown) +
             "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody>\n</table>\n";
  return out;
}

}  // namespace gridfree
