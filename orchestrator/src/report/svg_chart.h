// SPDX-License-Identifier: GPL-3.0-or-later
// A small, dependency-free SVG chart writer: line/scatter series with
// markers, linear or log axes with nice ticks, axis labels, legend, title,
// symmetric error bars, dashed horizontal reference lines.
//
// Output is a standalone <svg> element of fixed size (default 720×450, grown
// for a wide legend or wrapped text, see below) with
// no scripts, no external fonts or images, and deterministic bytes (same
// chart, same text), so it can be inlined in HTML, linked from Markdown, and
// compared in tests. All text is XML-escaped.
//
// Conventions:
//  - a point whose y is NaN has no value (e.g. a failed grid): it is drawn
//    with its marker on the bottom edge of the plot, never dropped;
//  - a point outside a fixed axis range is drawn as a small arrow on the
//    edge it left through, and counted in the note line;
//  - lines break at NaN values (and at non-positive values on log axes);
//  - text may hold sub/superscript markup "f_{0}" (svg_text.h);
//  - the legend column is as wide as its longest entry (never truncated):
//    when it needs more than 280 px the chart grows wider by the excess;
//  - no text leaves the chart: title, subtitle and note wrap at spaces to
//    the chart's width and the chart grows taller by the extra lines; an x
//    tick label at the edge moves in; a y tick or axis label too long for
//    its room gets a smaller font;
//  - a point label goes to the first of six places around its point (above
//    right, below left, above left, below right, right, left) inside the
//    plot that no marker, error bar, earlier label or drawn line touches,
//    and is left out when there is none.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/chart_axis.h"

namespace gridfree {

enum class Marker { none, circle, square, triangle, diamond, cross, x_mark };

struct ChartSeries {
  std::string name;               // legend text (markup allowed); empty = not in the legend
  std::vector<double> x, y;
  std::vector<double> y_error;    // empty, or one half-width per point (≤0/NaN: none)
  Marker marker = Marker::circle;
  bool line = true;               // connect consecutive points
  bool dashed = false;
  bool hollow = false;            // marker outline only
  int colour = -1;                // palette index; -1 = the series' position
  bool faded = false;             // drawn at 35 % opacity (e.g. a rejected fit)
  std::vector<std::string> point_labels = {};  // empty, or one small label per point ("" = none)
};

struct ChartHLine {
  double y = 0;
  std::string label;              // legend text
  int colour = 6;                 // palette index (6 = black)
  bool dashed = true;
};

struct ChartAxis {
  std::string label;                // may hold sub/superscript markup (svg_text.h)
  AxisScale scale = AxisScale::linear;
  std::optional<double> min, max;   // fixed limits; otherwise from the data
  // Log scale when the positive data span more than a decade (chart_axis.h
  // scale_for_span); a fixed min ≤ 0 is then dropped.
  bool auto_log = false;
  std::string tick_suffix = {};     // appended to every tick label, e.g. "%"
};

struct Chart {
  std::string id;                 // unique within a page (prefixes element ids)
  std::string title, subtitle;
  ChartAxis x, y;
  std::vector<ChartSeries> series;
  std::vector<ChartHLine> hlines;
  std::string note;               // one line of text under the plot
  int width = 720, height = 450;
  // The phone rendering (narrow_chart): a 15 px font, the legend under the
  // plot, no text that shrinks below 12 px.
  bool narrow = false;
};

// The same chart laid out for a phone: kNarrowWidth wide, `narrow` set,
// its element ids suffixed so both renderings can sit on one page.
inline constexpr int kNarrowWidth = 360;
Chart narrow_chart(const Chart& chart);

// Print-friendly, colour-blind-safe palette (Okabe & Ito), as "#rrggbb".
const char* palette_colour(int index);
// Marker shapes cycle with the series index (a second cue besides colour).
Marker marker_for(int index);

// The chart as an <svg> element (no XML declaration; add one for a file).
std::string render_svg(const Chart& chart);

// Width in pixels of the legend column for these entries (markup allowed).
double legend_width(const std::vector<std::string>& labels);

// The XML declaration of a standalone .svg file.
inline constexpr const char* kSvgDeclaration = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
// render_svg with an XML declaration, for a standalone .svg file.
std::string render_svg_file(const Chart& chart);

}  // namespace gridfree
