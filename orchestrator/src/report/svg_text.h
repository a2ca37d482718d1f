// SPDX-License-Identifier: GPL-3.0-or-later
// Chart text with sub- and superscripts. Labels are written in a small
// markup: "f_{0}" is f with subscript 0, "h^{p}" h with superscript p,
// "σ_{RE}/R_{f}" the fit-quality ratio. Everything else is plain text.
//
//   svg_rich_text  → XML-escaped SVG content, scripts as
//                    <tspan baseline-shift="sub|super" font-size="75%">
//   plain_text     → the same text without markup ("f0", "σRE/Rf") for
//                    <title>, aria-label and file captions
//   text_width_px  → estimated rendered width, used to size legends: DejaVu
//                    Sans averages ≈ 0.62 em per character (digits 0.64 em,
//                    lower case 0.6 em), scripts count at 75 %
//   wrap_markup    → the text broken at spaces (never inside a script or a
//                    word) into lines of at most max_px each; a single word
//                    longer than max_px is a line of its own
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gridfree {

std::string svg_rich_text(std::string_view markup);
std::string plain_text(std::string_view markup);
double text_width_px(std::string_view markup, double font_px);
std::vector<std::string> wrap_markup(std::string_view markup, double max_px, double font_px);

}  // namespace gridfree
