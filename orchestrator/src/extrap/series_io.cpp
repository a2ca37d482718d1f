// SPDX-License-Identifier: GPL-3.0-or-later
// JSON and CSV readers for a grid-convergence series.
#include "extrap/series_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "core/json_limits.h"

namespace gridfree {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Parses the whole cell as a number; nullopt-like failure via `ok`.
double parse_number(const std::string& cell, bool& ok) {
  ok = false;
  if (cell.empty()) return 0;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  ok = end == cell.c_str() + cell.size() && errno != ERANGE;
  return v;
}

std::vector<double> json_numbers(const nlohmann::json& doc, const char* key, ProblemList& problems) {
  std::vector<double> out;
  const std::string where = std::string("/") + key;
  if (!doc.contains(key)) {
    problems.add(where, "missing; expected an array of numbers");
    return out;
  }
  const auto& arr = doc.at(key);
  if (!arr.is_array()) {
    problems.add(where, "must be an array of numbers");
    return out;
  }
  for (std::size_t i = 0; i < arr.size(); ++i) {
    if (!arr[i].is_number()) {
      problems.add(where + "/" + std::to_string(i), "must be a number");
      out.push_back(0);
    } else {
      out.push_back(arr[i].get<double>());
    }
  }
  return out;
}

}  // namespace

Series parse_series_json(const std::string& text, const std::string& source) {
  const nlohmann::json doc = parse_json_text(text, source);  // limits: core/json_limits.h
  if (!doc.is_object())
    throw InputError(source, "expected an object {\"h\": [...], \"f\": [...]}");
  ProblemList problems;
  const auto h = json_numbers(doc, "h", problems);
  const auto f = json_numbers(doc, "f", problems);
  problems.throw_if_any();
  return make_series(h, f);
}

Series parse_series_csv(const std::string& text, const std::string& source) {
  std::stringstream in(text);
  std::string line;
  int line_no = 0;
  long h_col = -1, f_col = -1;
  std::vector<double> h, f;
  std::vector<int> row_line;  // file line of each data row
  ProblemList problems;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    const auto cells = split_csv_line(t);
    const std::string where = source + ":" + std::to_string(line_no);
    if (h_col < 0) {  // the first non-comment line is the header
      for (std::size_t c = 0; c < cells.size(); ++c) {
        const std::string name = lower(cells[c]);
        if (name == "h") h_col = static_cast<long>(c);
        if (name == "f") f_col = static_cast<long>(c);
      }
      if (h_col < 0 || f_col < 0)
        throw InputError(where, "header must name the columns h and f (e.g. \"h,f\"), got \"" + t + "\"");
      continue;
    }
    const auto needed = static_cast<std::size_t>(std::max(h_col, f_col));
    if (cells.size() <= needed) {
      problems.add(where, "expected at least " + std::to_string(needed + 1) + " columns, got " +
                              std::to_string(cells.size()));
      continue;
    }
    bool ok_h = false, ok_f = false;
    const double hv = parse_number(cells[static_cast<std::size_t>(h_col)], ok_h);
    const double fv = parse_number(cells[static_cast<std::size_t>(f_col)], ok_f);
    if (!ok_h) problems.add(where, "h = \"" + cells[static_cast<std::size_t>(h_col)] + "\" is not a number");
    if (!ok_f) problems.add(where, "f = \"" + cells[static_cast<std::size_t>(f_col)] + "\" is not a number");
    if (ok_h && !std::isfinite(hv)) problems.add(where, "h must be a finite number");
    if (ok_f && !std::isfinite(fv)) problems.add(where, "f must be a finite number");
    if (ok_h && std::isfinite(hv) && hv <= 0) problems.add(where, "h must be positive");
    h.push_back(hv);
    f.push_back(fv);
    row_line.push_back(line_no);
  }
  if (h_col < 0) throw InputError(source, "empty file: expected a header \"h,f\" and one row per grid");
  problems.throw_if_any();
  try {
    return make_series(h, f);
  } catch (const InputError& e) {  // "/h/3" -> the file line of data row 3
    std::vector<Problem> renamed = e.problems();
    for (auto& p : renamed) {
      const auto slash = p.where.rfind('/');
      std::size_t row = 0;
      if (slash != std::string::npos && slash > 0 &&
          std::sscanf(p.where.c_str() + slash + 1, "%zu", &row) == 1 && row < row_line.size())
        p.where = source + ":" + std::to_string(row_line[row]);
      else
        p.where = source;
    }
    throw InputError(renamed);
  }
}

Series read_series_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot open the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string ext = lower(path.extension().string());
  const std::string t = trim(text);
  const bool json = ext == ".json" || (ext != ".csv" && !t.empty() && t.front() == '{');
  Series s = json ? parse_series_json(text, path.string()) : parse_series_csv(text, path.string());
  if (s.size() > kMaxSeriesPoints)
    throw InputError(path.string(), "has " + std::to_string(s.size()) + " points; gridfree extrapolate takes at most " +
                                        std::to_string(kMaxSeriesPoints) +
                                        " (its power-law fit scans 4 000 orders over every point: about 2 s at the "
                                        "limit; docs/LIMITS.md). A grid series has tens of grids: thin the series "
                                        "or split it");
  return s;
}

}  // namespace gridfree
