// SPDX-License-Identifier: GPL-3.0-or-later
// Marker, arrow and error-bar elements (see svg_marker.h).
#include "report/svg_marker.h"

#include <cstdio>

namespace gridfree {

std::string px(double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.2f", value);
  std::string out = buffer;
  for (char& ch : out) {
    if (ch == ',') ch = '.';
  }
  if (out == "-0.00") out = "0.00";
  return out;
}

namespace {

std::string paint(const std::string& colour, bool hollow) {
  return hollow ? " fill=\"#ffffff\" stroke=\"" + colour + "\" stroke-width=\"1.5\""
                : " fill=\"" + colour + "\" stroke=\"" + colour + "\" stroke-width=\"1\"";
}

std::string polygon(const std::string& points, const std::string& attributes) {
  return "<polygon points=\"" + points + "\"" + attributes + "/>";
}

}  // namespace

std::string svg_marker(Marker marker, double cx, double cy, const std::string& colour, bool hollow) {
  const double r = 4.0;
  switch (marker) {
    case Marker::none:
      return {};
    case Marker::circle:
      return "<circle cx=\"" + px(cx) + "\" cy=\"" + px(cy) + "\" r=\"" + px(r) + "\"" +
             paint(colour, hollow) + "/>";
    case Marker::square:
      return "<rect x=\"" + px(cx - r * 0.9) + "\" y=\"" + px(cy - r * 0.9) + "\" width=\"" +
             px(1.8 * r) + "\" height=\"" + px(1.8 * r) + "\"" + paint(colour, hollow) + "/>";
    case Marker::triangle:
      return polygon(px(cx) + "," + px(cy - 1.2 * r) + " " + px(cx - 1.1 * r) + "," +
                         px(cy + 0.8 * r) + " " + px(cx + 1.1 * r) + "," + px(cy + 0.8 * r),
                     paint(colour, hollow));
    case Marker::diamond:
      return polygon(px(cx) + "," + px(cy - 1.3 * r) + " " + px(cx + 1.1 * r) + "," + px(cy) +
                         " " + px(cx) + "," + px(cy + 1.3 * r) + " " + px(cx - 1.1 * r) + "," +
                         px(cy),
                     paint(colour, hollow));
    case Marker::cross:
      return "<path d=\"M" + px(cx - r) + " " + px(cy) + "H" + px(cx + r) + "M" + px(cx) + " " +
             px(cy - r) + "V" + px(cy + r) + "\" stroke=\"" + colour +
             "\" stroke-width=\"2\" fill=\"none\"/>";
    case Marker::x_mark:
      return "<path d=\"M" + px(cx - r) + " " + px(cy - r) + "L" + px(cx + r) + " " + px(cy + r) +
             "M" + px(cx - r) + " " + px(cy + r) + "L" + px(cx + r) + " " + px(cy - r) +
             "\" stroke=\"" + colour + "\" stroke-width=\"2.2\" fill=\"none\"/>";
  }
  return {};
}

std::string svg_offscale_arrow(double cx, double cy, int dx, int dy, const std::string& colour) {
  const double s = 6.0;
  // Tip at (cx, cy) + s·(dx, dy); base perpendicular to the direction.
  const double tx = cx + s * dx, ty = cy + s * dy;
  const double bx = -dy, by = dx;  // perpendicular
  return polygon(px(tx) + "," + px(ty) + " " + px(cx + 0.7 * s * bx) + "," + px(cy + 0.7 * s * by) +
                     " " + px(cx - 0.7 * s * bx) + "," + px(cy - 0.7 * s * by),
                 " fill=\"" + colour + "\" stroke=\"none\"");
}

std::string svg_error_bar(double cx, double y_low, double y_high, const std::string& colour) {
  const double cap = 4.0;
  return "<path d=\"M" + px(cx) + " " + px(y_low) + "V" + px(y_high) + "M" + px(cx - cap) + " " +
         px(y_low) + "H" + px(cx + cap) + "M" + px(cx - cap) + " " + px(y_high) + "H" +
         px(cx + cap) + "\" stroke=\"" + colour + "\" stroke-width=\"1.2\" fill=\"none\"/>";
}

}  // namespace gridfree
