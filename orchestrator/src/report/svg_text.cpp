// SPDX-License-Identifier: GPL-3.0-or-later
// Markup "_{…}" / "^{…}" to SVG tspans (see svg_text.h).
#include "report/svg_text.h"

#include "report/text_format.h"

namespace gridfree {

namespace {

// Calls piece(text, shift) for each run: shift 0 = baseline, −1 = sub, +1 = super.
template <typename F>
void for_each_run(std::string_view s, F&& piece) {
  std::size_t start = 0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if ((s[i] != '_' && s[i] != '^') || s[i + 1] != '{') continue;
    const std::size_t close = s.find('}', i + 2);
    if (close == std::string_view::npos) break;
    if (i > start) piece(s.substr(start, i - start), 0);
    piece(s.substr(i + 2, close - i - 2), s[i] == '_' ? -1 : 1);
    start = close + 1;
    i = close;
  }
  if (start < s.size()) piece(s.substr(start), 0);
}

std::size_t code_points(std::string_view s) {
  std::size_t n = 0;
  for (char ch : s) n += (static_cast<unsigned char>(ch) & 0xC0) != 0x80 ? 1 : 0;
  return n;
}

}  // namespace

std::string svg_rich_text(std::string_view markup) {
  std::string out;
  for_each_run(markup, [&](std::string_view text, int shift) {
    if (shift == 0) {
      out += xml_escape(text);
    } else {
      out += std::string("<tspan baseline-shift=\"") + (shift < 0 ? "sub" : "super") + "\" font-size=\"75%\">" +
             xml_escape(text) + "</tspan>";
    }
  });
  return out;
}

std::string plain_text(std::string_view markup) {
  std::string out;
  for_each_run(markup, [&](std::string_view text, int) { out += text; });
  return out;
}

double text_width_px(std::string_view markup, double font_px) {
  double width = 0;
  for_each_run(markup, [&](std::string_view text, int shift) {
    width += static_cast<double>(code_points(text)) * 0.62 * font_px * (shift == 0 ? 1.0 : 0.75);
  });
  return width;
}

std::vector<std::string> wrap_markup(std::string_view markup, double max_px, double font_px) {
  // Words: runs between spaces that are not inside "_{…}" / "^{…}".
  std::vector<std::string_view> words;
  std::size_t start = 0;
  int depth = 0;
  for (std::size_t i = 0; i < markup.size(); ++i) {
    if (markup[i] == '{') ++depth;
    if (markup[i] == '}' && depth > 0) --depth;
    if (markup[i] != ' ' || depth > 0) continue;
    if (i > start) words.push_back(markup.substr(start, i - start));
    start = i + 1;
  }
  if (start < markup.size()) words.push_back(markup.substr(start));
  std::vector<std::string> lines;
  for (std::string_view w : words) {
    if (!lines.empty()) {
      const std::string longer = lines.back() + " " + std::string(w);
      if (text_width_px(longer, font_px) <= max_px) {
        lines.back() = longer;
        continue;
      }
    }
    lines.emplace_back(w);
  }
  return lines;
}

}  // namespace gridfree
