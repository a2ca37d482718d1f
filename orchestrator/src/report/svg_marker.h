// SPDX-License-Identifier: GPL-3.0-or-later
// SVG elements for point markers, off-scale arrows and error bars, centred
// on pixel coordinates (used by svg_chart.cpp).
#pragma once

#include <string>

#include "report/svg_chart.h"

namespace gridfree {

// Pixel coordinate with two decimals, C locale: "123.45".
std::string px(double value);

// One marker of the given shape at (cx, cy), about 8 px across.
std::string svg_marker(Marker marker, double cx, double cy, const std::string& colour, bool hollow);

// A small triangle at (cx, cy) pointing in direction (dx, dy) ∈ {−1,0,1}²:
// a point beyond the axis range, drawn on the edge it left through.
std::string svg_offscale_arrow(double cx, double cy, int dx, int dy, const std::string& colour);

// A vertical error bar from y_low to y_high (pixels) at x, with caps.
std::string svg_error_bar(double cx, double y_low, double y_high, const std::string& colour);

}  // namespace gridfree
