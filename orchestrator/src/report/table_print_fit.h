// How a report table is laid out on paper. In print a number cell never
// breaks (white-space: nowrap) and a text cell breaks only at spaces, so a
// table's narrowest printed width is the sum of its columns' narrowest
// widths: a number cell's whole text, a text cell's or header's longest
// word. From that width, estimated at ≈ 0.62 em per character (DejaVu Sans,
// as svg_text.h; bold headers 10 % wider) plus each cell's padding and
// border, the table is given the first layout that holds it:
//   fit-portrait        6.5 pt on an A4 portrait page (190 mm of text width)
//   fit-landscape       6.5 pt on an A4 landscape page of its own (277 mm)
//   fit-landscape-small 5 pt on an A4 landscape page
// A table wider still keeps fit-landscape-small (the last columns may then
// be cut in print; on screen every table scrolls sideways).
#pragma once

#include <string>

#include "report/table.h"

namespace gridfree {

// The narrowest printed width of the table in points at font size font_pt.
double narrowest_print_width_pt(const Table& table, double font_pt);
// "fit-portrait", "fit-landscape" or "fit-landscape-small".
std::string print_fit_class(const Table& table);

}  // namespace gridfree
