// SPDX-License-Identifier: GPL-3.0-or-later
#include "external/quantity_read.h"

#include <cstdlib>
#include <vector>

namespace gridfree {
namespace {

// Calls f(line, number) for each line of text (no trailing '\n' or '\r').
template <class F>
void for_each_line(std::string_view text, F&& f) {
  int number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!f(line, ++number)) return;
    start = end + 1;
  }
}

bool is_record_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '(' || c == ')'; }

std::vector<std::string_view> record_columns(std::string_view row) {
  std::vector<std::string_view> cols;
  std::size_t i = 0;
  while (i < row.size()) {
    while (i < row.size() && is_record_space(row[i])) ++i;
    const std::size_t start = i;
    while (i < row.size() && !is_record_space(row[i])) ++i;
    if (i > start) cols.push_back(row.substr(start, i - start));
  }
  return cols;
}

bool is_data_row(std::string_view line) {
  for (char c : line) {
    if (c == '#') return false;
    if (!is_record_space(c)) return true;
  }
  return false;
}

bool is_blank_line(std::string_view line) {
  for (char c : line)
    if (c != ' ' && c != '\t' && c != '\r') return false;
  return true;
}

std::string cut_line(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s.substr(0, 160));
}

}  // namespace

std::optional<double> parse_record_number(std::string_view token) {
  if (token.empty() || token.size() > 64) return std::nullopt;
  const std::string s(token);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

QuantityRecords read_column(std::string_view text, int column) {
  std::string_view last_row, previous_row;
  for_each_line(text, [&](std::string_view line, int) {
    if (is_data_row(line)) {
      previous_row = last_row;
      last_row = line;
    }
    return true;
  });
  QuantityRecords r;
  if (last_row.empty()) {
    r.problem = "no data row (only comments or nothing)";
    return r;
  }
  const auto cols = record_columns(last_row);
  if (column >= static_cast<int>(cols.size())) {
    r.problem = "column " + std::to_string(column) + " is not in the last row (" + std::to_string(cols.size()) +
                " columns, counted from 0: \"" + cut_line(last_row) + "\")";
    return r;
  }
  r.last = parse_record_number(cols[column]);
  if (!r.last) {
    r.problem = "\"" + std::string(cols[column].substr(0, 40)) + "\" in column " + std::to_string(column) +
                " of the last row is not a number";
    return r;
  }
  if (!previous_row.empty()) {
    const auto prev = record_columns(previous_row);
    if (column < static_cast<int>(prev.size())) r.previous = parse_record_number(prev[column]);
  }
  return r;
}

QuantityRecords read_regex(std::string_view text, const std::regex& re, const std::string& regex_text) {
  std::optional<std::string> last, previous;
  for_each_line(text, [&](std::string_view line, int) {
    std::match_results<std::string_view::const_iterator> m;
    if (std::regex_search(line.begin(), line.end(), m, re) && m.size() > 1 && m[1].matched) {
      previous = std::move(last);
      last = m[1].str();
    }
    return true;
  });
  QuantityRecords r;
  if (!last) {
    r.problem = "no line matches \"" + regex_text + "\"";
    return r;
  }
  r.last = parse_record_number(*last);
  if (!r.last) {
    r.problem = "the last match \"" + last->substr(0, 40) + "\" of \"" + regex_text + "\" is not a number";
    return r;
  }
  if (previous) r.previous = parse_record_number(*previous);
  return r;
}

std::optional<PatternHit> find_pattern(std::string_view text, const std::vector<std::regex>& patterns,
                                       const std::vector<std::string>& pattern_texts) {
  std::optional<PatternHit> hit;
  for_each_line(text, [&](std::string_view line, int number) {
    if (hit) {  // the first non-empty line after the hit, for context
      if (is_blank_line(line)) return true;
      hit->text += " | " + cut_line(line);
      return false;
    }
    for (std::size_t i = 0; i < patterns.size(); ++i)
      if (std::regex_search(line.begin(), line.end(), patterns[i])) {
        hit = PatternHit{pattern_texts[i], number, cut_line(line)};
        break;
      }
    return true;
  });
  return hit;
}

}  // namespace gridfree
