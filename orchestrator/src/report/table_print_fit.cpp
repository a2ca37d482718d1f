// SPDX-License-Identifier: GPL-3.0-or-later
// Print layout of a report table from its narrowest width (see table_print_fit.h).
#include "report/table_print_fit.h"

#include <algorithm>

#include "report/svg_text.h"

namespace gridfree {

namespace {

constexpr double kCellPaddingPt = 2 * 1.5 + 0.75;  // 2 px padding each side, 1 px border (1 px = 0.75 pt)
constexpr double kProseMinChars = 12;              // td.prose keeps a readable column

double longest_word_pt(const std::string& text, double font_pt) {
  double widest = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    widest = std::max(widest, text_width_px(std::string_view(text).substr(start, end - start), font_pt));
    start = end + 1;
  }
  return widest;
}

}  // namespace

double narrowest_print_width_pt(const Table& table, double font_pt, bool numbers_break_at_spaces) {
  double total = 0;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const Column& col = table.columns[c];
    if (col.csv_only || col.screen_only) continue;  // not printed
    double width = 1.1 * longest_word_pt(col.title.empty() ? col.name : col.title, font_pt);
    if (col.prose) width = std::max(width, kProseMinChars * 0.62 * font_pt);
    for (const auto& row : table.rows) {
      if (c >= row.size()) continue;
      const std::string& shown = row[c].shown;
      const bool whole = col.numeric && !numbers_break_at_spaces;
      width = std::max(width, whole ? text_width_px(shown, font_pt) : longest_word_pt(shown, font_pt));
    }
    total += width + kCellPaddingPt;
  }
  return total;
}

std::string print_fit_class(const Table& table) {
  constexpr double kMmToPt = 72.0 / 25.4;
  const double portrait = 190 * kMmToPt, landscape = 277 * kMmToPt;
  if (narrowest_print_width_pt(table, 6.5) <= portrait) return "fit-portrait";
  if (narrowest_print_width_pt(table, 6.5) <= landscape) return "fit-landscape";
  return "fit-landscape-small";
}

}  // namespace gridfree
