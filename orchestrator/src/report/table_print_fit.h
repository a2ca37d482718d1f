// SPDX-License-Identifier: GPL-3.0-or-later
// How a report table is laid out on paper. In print a text cell or header
// breaks only at spaces, never inside a word or a number, and a number cell
// does not break at all (fit-portrait, fit-landscape) or only at its spaces
// (fit-landscape-small: "1016.995 ± 4.2" may become "1016.995 ±" / "4.2").
// A table's narrowest printed width is then the sum of its columns'
// narrowest widths: a number cell's whole text (or its longest word), a
// text cell's or header's longest word, estimated at ≈ 0.62 em per
// character (DejaVu Sans, as svg_text.h; bold headers 10 % wider) plus each
// cell's padding and border. The table gets the first layout that holds it:
//   fit-portrait        6.5 pt on an A4 portrait page (190 mm of text width)
//   fit-landscape       6.5 pt on an A4 landscape page of its own (277 mm)
//   fit-landscape-small 5 pt on an A4 landscape page, number cells breaking
//                       at their spaces
// A table wider still keeps fit-landscape-small (its last columns may then
// be cut in print; on screen every table scrolls sideways in its box).
#pragma once

#include <string>

#include "report/table.h"

namespace gridfree {

// The narrowest printed width of the table in points at font size font_pt,
// number cells whole or (numbers_break_at_spaces) by their longest word.
double narrowest_print_width_pt(const Table& table, double font_pt, bool numbers_break_at_spaces = false);
// "fit-portrait", "fit-landscape" or "fit-landscape-small".
std::string print_fit_class(const Table& table);

}  // namespace gridfree
