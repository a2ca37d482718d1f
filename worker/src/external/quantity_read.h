// SPDX-License-Identifier: GPL-3.0-or-later
// Reading a quantity's records out of a file's text (docs/EXTERNAL.md
// "Collection"). Pure functions over the text; the driver reads the files.
#pragma once

#include <optional>
#include <regex>
#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

// The last two records of a quantity. `last` empty: `problem` says why
// ("no data row", "column 3 is not in the last row (2 columns)", ...).
// A record that reads as nan or inf is kept (the classification calls it
// diverged).
struct QuantityRecords {
  std::optional<double> last;
  std::optional<double> previous;
  std::string problem;
};

// A whole token as a number (strtod: also nan and inf); nullopt otherwise.
std::optional<double> parse_record_number(std::string_view token);

// Column `column` (0-based) of the last two data rows: rows that are not
// empty and do not start with '#'; columns split at whitespace, with
// parentheses counting as whitespace, so an OpenFOAM vector (a b c) gives
// three columns.
QuantityRecords read_column(std::string_view text, int column);

// The first capture group of the last two lines `re` matches.
QuantityRecords read_regex(std::string_view text, const std::regex& re, const std::string& regex_text);

// The first line matching one of the patterns: the pattern's text, the
// 1-based line number, the line and the next non-empty one (each cut to 160
// characters) — an OpenFOAM FOAM FATAL ERROR says what went wrong on the
// lines after the banner.
struct PatternHit {
  std::string pattern;
  int line = 0;
  std::string text;
};
std::optional<PatternHit> find_pattern(std::string_view text, const std::vector<std::regex>& patterns,
                                       const std::vector<std::string>& pattern_texts);

}  // namespace gridfree
