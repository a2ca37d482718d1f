// SPDX-License-Identifier: GPL-3.0-or-later
// Small text helpers shared by the particle file readers.
#pragma once

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/input_error.h"

namespace gridfree::text {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '\n')) s.remove_suffix(1);
  return s;
}

// Fields separated by any of `separators`; runs of separators count as one
// when `merge` (whitespace-separated formats), else every separator splits.
inline std::vector<std::string_view> split(std::string_view line, std::string_view separators, bool merge) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    if (i == line.size() || separators.find(line[i]) != std::string_view::npos) {
      std::string_view field = trim(line.substr(start, i - start));
      if (!merge || !field.empty()) out.push_back(field);
      start = i + 1;
    }
  }
  return out;
}

// A finite double; Fortran exponents ("1.0D-3") are accepted when `fortran`.
inline std::optional<double> parse_double(std::string_view s, bool fortran = false) {
  s = trim(s);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  std::string buffer;
  if (fortran && s.find_first_of("dD") != std::string_view::npos) {
    buffer.assign(s);
    for (char& c : buffer)
      if (c == 'd' || c == 'D') c = 'e';
    s = buffer;
  }
  double x = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(x)) return std::nullopt;
  return x;
}

inline std::string at_line(const std::filesystem::path& file, int line) {
  return file.string() + ":" + std::to_string(line);
}

// All lines of a file (without line terminators); InputError if unreadable.
inline std::vector<std::string> read_lines(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), "cannot open the file");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace gridfree::text
