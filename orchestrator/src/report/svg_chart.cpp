// SPDX-License-Identifier: GPL-3.0-or-later
// SVG rendering of a Chart (see svg_chart.h for the conventions).
//
// Layout (pixels): title band on top, y tick labels on the left, x tick
// labels and axis label below, an optional note line at the bottom and an
// optional legend column on the right whose width follows the longest label.
#include "report/svg_chart.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "report/svg_marker.h"
#include "report/svg_text.h"
#include "report/text_format.h"

namespace gridfree {

namespace {

constexpr std::array<const char*, 8> kPalette = {
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#7F7F7F"};
constexpr std::array<Marker, 6> kMarkers = {Marker::circle, Marker::square,  Marker::triangle,
                                            Marker::diamond, Marker::x_mark, Marker::cross};
constexpr double kFont = 12.0;
constexpr double kNarrowFont = 15.0;     // 75 % sub/superscripts stay ≥ 11 px at 1:1
constexpr double kNarrowMinFont = 12.0;  // tick and axis labels never shrink below this

bool usable(double v, AxisScale scale) {
  return std::isfinite(v) && (scale == AxisScale::linear || v > 0);
}

// Data extent along one axis; `values` already filtered to usable ones.
AxisTicks axis_ticks(const ChartAxis& axis, std::vector<double> values, int target) {
  if (axis.min) values.push_back(*axis.min);
  if (axis.max) values.push_back(*axis.max);
  double lo = axis.scale == AxisScale::log ? 1.0 : 0.0;
  double hi = axis.scale == AxisScale::log ? 10.0 : 1.0;
  if (!values.empty()) {
    lo = *std::min_element(values.begin(), values.end());
    hi = *std::max_element(values.begin(), values.end());
  }
  AxisTicks ticks = axis.scale == AxisScale::log ? log_ticks(lo, hi) : linear_ticks(lo, hi, target);
  if (axis.min) ticks.lo = *axis.min;
  if (axis.max) ticks.hi = *axis.max;
  if (axis.min || axis.max) {
    const double slack = 1e-9 * std::abs(ticks.hi - ticks.lo);
    auto outside = [&](double v) { return v < ticks.lo - slack || v > ticks.hi + slack; };
    std::erase_if(ticks.major, outside);
    std::erase_if(ticks.minor, outside);
  }
  return ticks;
}

std::string text(double x, double y, const std::string& content, const std::string& extra = {}) {
  return "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"" + extra + ">" + svg_rich_text(content) +
         "</text>";
}

struct LegendEntry {
  std::string label, colour;
  Marker marker;
  bool line, dashed, hollow, faded;
};

// The axis rule (chart_axis.h scale_for_span) applied to an auto_log axis.
void resolve_scale(ChartAxis& axis, const std::vector<double>& values) {
  if (!axis.auto_log || values.empty()) return;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (scale_for_span(*lo, *hi) != AxisScale::log) return;
  axis.scale = AxisScale::log;
  if (axis.min && *axis.min <= 0) axis.min.reset();
  if (axis.max && *axis.max <= 0) axis.max.reset();
}

// Boxes already taken (markers, error bars, placed labels) and the lines
// drawn (series, fits, reference lines), to keep point labels apart from
// each other and off the points and lines; a label must also lie inside the
// plot area.
struct LabelBoxes {
  struct Box { double x0, y0, x1, y1; };
  struct Segment { double xa, ya, xb, yb; };
  Box area;
  std::vector<Box> boxes;
  std::vector<Segment> lines;
  // Whether the segment passes through the box (Liang–Barsky clipping).
  static bool crosses(const Segment& s, const Box& b) {
    double t0 = 0, t1 = 1;
    const double dx = s.xb - s.xa, dy = s.yb - s.ya;
    for (const auto& [p, q] : {std::pair{-dx, s.xa - b.x0}, std::pair{dx, b.x1 - s.xa}, std::pair{-dy, s.ya - b.y0},
                               std::pair{dy, b.y1 - s.ya}}) {
      if (p == 0) {
        if (q < 0) return false;
        continue;
      }
      const double t = q / p;
      if (p < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
      if (t0 > t1) return false;
    }
    return true;
  }
  bool place(const Box& b) {
    if (b.x0 < area.x0 || b.x1 > area.x1 || b.y0 < area.y0 || b.y1 > area.y1) return false;
    for (const Box& o : boxes) {
      if (b.x0 < o.x1 && o.x0 < b.x1 && b.y0 < o.y1 && o.y0 < b.y1) return false;
    }
    for (const Segment& l : lines) {
      if (crosses(l, b)) return false;
    }
    boxes.push_back(b);
    texts.push_back(b);
    return true;
  }
  // A label moved away from its point: the box must be free and the leader
  // from the point to it must cross no other label (it may pass a marker);
  // both are then taken.
  bool place_with_leader(const Box& b, const Segment& leader) {
    for (const Box& o : texts)
      if (crosses(leader, o)) return false;
    if (!place(b)) return false;
    lines.push_back(leader);
    return true;
  }
  std::vector<Box> texts;  // the placed labels' boxes
};

// A point label of font 10 at the first free place around its point
// (above right, below left, above left, below right, right, left); when
// every one collides, farther out on rings of growing radius with a thin
// leader line back to the point; "" only when no place in the plot is free
// (the caller counts those and says so in the chart's note).
std::string point_label(LabelBoxes& taken, double x, double y, const std::string& label, double font = 10.0) {
  const double w = text_width_px(label, font);
  const double grow = font - 10.0;  // a larger font: the box grows up and the places move out
  struct Place { double dx, baseline; bool end; };
  for (const Place& p : {Place{5, -7, false}, Place{-5, 16, true}, Place{-5, -7, true}, Place{5, 16, false},
                         Place{7, 4, false}, Place{-7, 4, true}}) {
    const double x0 = p.end ? x + p.dx - w : x + p.dx;
    const double baseline = y + p.baseline + (p.baseline > 10 ? grow : 0);
    if (!taken.place({x0, baseline - 9 - grow, x0 + w, baseline + 2})) continue;
    return text(x + p.dx, baseline, label,
                " class=\"point-label\" font-size=\"" + format_g(font, 3) + "\" fill=\"#555\"" +
                    (p.end ? " text-anchor=\"end\"" : ""));
  }
  constexpr double kPi = 3.14159265358979323846;
  for (double r = 24; r <= 160; r += 12) {
    for (int k = 0; k < 16; ++k) {
      const double a = kPi / 2 - k * kPi / 8;  // from straight up, clockwise
      const double ax = x + r * std::cos(a), ay = y - r * std::sin(a);
      const bool end = std::cos(a) < -1e-9;    // left of the point: the text ends at the anchor
      const double x0 = end ? ax - w : ax, baseline = ay + 4;
      const LabelBoxes::Box box{x0, baseline - 9 - grow, x0 + w, baseline + 2};
      // The leader stops 2 px short of the label's box.
      const double ex = end ? box.x1 + 2 : box.x0 - 2, ey = std::clamp(y, box.y0, box.y1);
      if (!taken.place_with_leader(box, {x, y, ex, ey})) continue;
      return "<line class=\"leader\" x1=\"" + format_g(x, 6) + "\" y1=\"" + format_g(y, 6) + "\" x2=\"" +
             format_g(ex, 6) + "\" y2=\"" + format_g(ey, 6) + "\" stroke=\"#999\" stroke-width=\"0.6\"/>\n" +
             text(ax, baseline, label,
                  " class=\"point-label\" font-size=\"" + format_g(font, 3) + "\" fill=\"#555\"" +
                      (end ? " text-anchor=\"end\"" : ""));
    }
  }
  return {};
}

// Font size at which `markup` is at most max_px wide (font_px if it fits).
double fitting_font(const std::string& markup, double font_px, double max_px, double min_px = 0.0) {
  const double w = text_width_px(markup, font_px);
  return w <= max_px ? font_px : std::max(min_px, std::floor(font_px * max_px / w * 10) / 10);
}

}  // namespace

const char* palette_colour(int index) {
  const int n = static_cast<int>(kPalette.size());
  return kPalette[static_cast<std::size_t>(((index % n) + n) % n)];
}

Marker marker_for(int index) {
  const int n = static_cast<int>(kMarkers.size());
  return kMarkers[static_cast<std::size_t>(((index % n) + n) % n)];
}

Chart narrow_chart(const Chart& chart) {
  Chart out = chart;
  out.narrow = true;
  out.width = kNarrowWidth;
  out.height = 400;
  out.id = (chart.id.empty() ? chart.title : chart.id) + "-n";
  return out;
}

double legend_width(const std::vector<std::string>& labels) {
  double widest = 0;
  for (const auto& l : labels) widest = std::max(widest, text_width_px(l, kFont));
  return labels.empty() ? 0.0 : std::max(110.0, 44.0 + widest);
}

namespace {

// One layout of the chart; the point labels no place was free for are
// added to `unplaced`.
std::string render_svg_once(const Chart& given, std::vector<std::string>& unplaced) {
  Chart chart = given;
  {
    std::vector<double> xs, ys;
    for (const auto& s : chart.series) {
      for (double v : s.x) if (std::isfinite(v)) xs.push_back(v);
      for (double v : s.y) if (std::isfinite(v)) ys.push_back(v);
    }
    for (const auto& h : chart.hlines) if (std::isfinite(h.y)) ys.push_back(h.y);
    resolve_scale(chart.x, xs);
    resolve_scale(chart.y, ys);
  }
  const std::string id = slugify(chart.id.empty() ? chart.title : chart.id);
  // 1. Axis ranges from the data.
  std::vector<double> xs, ys;
  for (const auto& s : chart.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (usable(s.x[i], chart.x.scale)) xs.push_back(s.x[i]);
      const double y = i < s.y.size() ? s.y[i] : NAN;
      if (!usable(y, chart.y.scale)) continue;
      ys.push_back(y);
      const double e = i < s.y_error.size() ? s.y_error[i] : NAN;
      if (std::isfinite(e) && e > 0) {
        ys.push_back(y + e);
        if (usable(y - e, chart.y.scale)) ys.push_back(y - e);
      }
    }
  }
  for (const auto& h : chart.hlines) {
    if (usable(h.y, chart.y.scale)) ys.push_back(h.y);
  }
  const AxisTicks xt = axis_ticks(chart.x, xs, 7);
  const AxisTicks yt = axis_ticks(chart.y, ys, 6);

  // Points off a fixed axis range become arrows, counted in the note line.
  int offscale_count = 0;
  {
    const AxisMap ux{chart.x.scale, xt.lo, xt.hi, 0, 1}, uy{chart.y.scale, yt.lo, yt.hi, 1, 0};
    for (const auto& s : chart.series) {
      for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()) && s.marker != Marker::none; ++i)
        if (!(ux.contains(s.x[i]) && (std::isnan(s.y[i]) || uy.contains(s.y[i])))) ++offscale_count;
    }
  }

  // 2. Layout.
  std::vector<LegendEntry> legend;
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const auto& s = chart.series[i];
    if (s.name.empty()) continue;
    legend.push_back({s.name, palette_colour(s.colour >= 0 ? s.colour : int(i)), s.marker, s.line, s.dashed,
                      s.hollow, s.faded});
  }
  for (const auto& h : chart.hlines) {
    if (!h.label.empty()) {
      legend.push_back({h.label, palette_colour(h.colour), Marker::none, true, h.dashed, false, false});
    }
  }
  std::vector<std::string> legend_labels;
  for (const auto& e : legend) legend_labels.push_back(e.label);
  // Narrow (a phone): a larger font, the legend under the plot, no text
  // below kNarrowMinFont (docs/REPORTS.md "Phone").
  const bool narrow = chart.narrow;
  const double font = narrow ? kNarrowFont : kFont;
  const double min_font = narrow ? kNarrowMinFont : 0.0;
  const double legend_w = narrow ? 0.0 : legend_width(legend_labels);
  if (legend_w > 280.0) chart.width += static_cast<int>(std::ceil(legend_w - 280.0));
  // Title, subtitle and note wrap to the chart's width; the chart grows by
  // the extra lines, so the plot keeps its size.
  const double title_scale = 1.1;  // bold text is about 10 % wider
  std::vector<std::string> title_lines = wrap_markup(chart.title, (chart.width - 24) / title_scale, 15.0);
  if (title_lines.empty()) title_lines.emplace_back();
  const std::vector<std::string> subtitle_lines = wrap_markup(chart.subtitle, chart.width - 24.0, font);
  const double line_step = narrow ? font + 4 : 15.0;  // subtitle and note lines
  std::string note = chart.note;
  if (offscale_count > 0) {
    note += std::string(note.empty() ? "" : " ") + std::to_string(offscale_count) +
            (offscale_count == 1 ? " point" : " points") + " off scale (arrows on the edge).";
  }
  const double left = 78, right = chart.width - 16 - legend_w;
  const double note_font = narrow ? font : 11.0;
  const std::vector<std::string> note_lines =
      wrap_markup(note, chart.width - (narrow ? 24.0 : left + 12.0), note_font);
  const double title_bottom = 22.0 + 19.0 * double(title_lines.size() - 1);
  const double top = subtitle_lines.empty() ? title_bottom + 22.0
                                            : title_bottom + 18.0 + line_step * double(subtitle_lines.size() - 1) + 20.0;
  const double note_step = narrow ? line_step : 14.0;
  const int extra_note = static_cast<int>(note_step * std::max(0, int(note_lines.size()) - 1));
  const double legend_step = font + 6;
  const int legend_h = narrow && !legend.empty() ? static_cast<int>(legend_step * double(legend.size()) + 8) : 0;
  const int x_label_room = narrow ? 10 : 0;
  chart.height += static_cast<int>(std::ceil(top - (subtitle_lines.empty() ? 44.0 : 60.0))) + extra_note + legend_h +
                  x_label_room;
  // Room for the x label, the legend (narrow) and the note lines.
  const double bottom = chart.height - 66.0 - extra_note - legend_h - x_label_room;
  const AxisMap mx{chart.x.scale, xt.lo, xt.hi, left, right};
  const AxisMap my{chart.y.scale, yt.lo, yt.hi, bottom, top};

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << chart.width << "\" height=\""
      << chart.height << "\" viewBox=\"0 0 " << chart.width << " " << chart.height
      << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" << font
      << "\" role=\"img\" aria-label=\"" << xml_escape(plain_text(chart.title)) << "\">\n";
  svg << "<title>" << xml_escape(plain_text(chart.title)) << "</title>\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  svg << "<defs><clipPath id=\"" << id << "-plot\"><rect x=\"" << px(left) << "\" y=\"" << px(top)
      << "\" width=\"" << px(right - left) << "\" height=\"" << px(bottom - top)
      << "\"/></clipPath></defs>\n";
  for (std::size_t i = 0; i < title_lines.size(); ++i)
    svg << text(chart.width / 2.0, 22 + 19.0 * double(i), title_lines[i],
                " text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\"")
        << "\n";
  for (std::size_t i = 0; i < subtitle_lines.size(); ++i)
    svg << text(chart.width / 2.0, title_bottom + 18 + line_step * double(i), subtitle_lines[i],
                " text-anchor=\"middle\" fill=\"#444444\"")
        << "\n";

  // 3. Grid, ticks, labels.
  svg << "<g stroke=\"#e3e3e3\" stroke-width=\"1\">";
  for (double v : xt.major) svg << "<path d=\"M" << px(mx(v)) << " " << px(top) << "V" << px(bottom) << "\"/>";
  for (double v : yt.major) svg << "<path d=\"M" << px(left) << " " << px(my(v)) << "H" << px(right) << "\"/>";
  svg << "</g>\n<g stroke=\"#333333\" stroke-width=\"1\">";
  for (double v : xt.major) svg << "<path d=\"M" << px(mx(v)) << " " << px(bottom) << "v5\"/>";
  for (double v : xt.minor) svg << "<path d=\"M" << px(mx(v)) << " " << px(bottom) << "v3\"/>";
  for (double v : yt.major) svg << "<path d=\"M" << px(left) << " " << px(my(v)) << "h-5\"/>";
  for (double v : yt.minor) svg << "<path d=\"M" << px(left) << " " << px(my(v)) << "h-3\"/>";
  svg << "</g>\n<g fill=\"#222222\">";
  // Tick labels stay inside the chart: an x label at the edge moves in, a
  // y label wider than the margin gets a smaller font.
  for (double v : xt.major) {
    const std::string label = format_tick(v, xt, chart.x.scale) + chart.x.tick_suffix;
    const double half = text_width_px(label, font) / 2;
    svg << text(std::clamp(mx(v), 2 + half, chart.width - 2 - half), bottom + 6 + font, label, " text-anchor=\"middle\"");
  }
  for (double v : yt.major) {
    const std::string label = format_tick(v, yt, chart.y.scale) + chart.y.tick_suffix;
    const double fit = fitting_font(label, font, left - 32, min_font);  // right of the y axis label
    svg << text(left - 8, my(v) + 4, label,
                " text-anchor=\"end\"" + (fit < font ? " font-size=\"" + format_g(fit, 3) + "\"" : std::string()));
  }
  svg << "</g>\n";
  auto axis_font = [&](const std::string& label, double room) {
    const double fit = fitting_font(label, font, room, min_font);
    return fit < font ? " font-size=\"" + format_g(fit, 3) + "\"" : std::string();
  };
  // The x label under the plot's middle, or the chart's when wider than the plot.
  const double xmid = text_width_px(chart.x.label, font) <= right - left ? (left + right) / 2 : chart.width / 2.0;
  svg << text(xmid, bottom + 26 + font + x_label_room, chart.x.label, " text-anchor=\"middle\"" + axis_font(chart.x.label, chart.width - 4.0))
      << "\n";
  const double ymid = (top + bottom) / 2;
  svg << text(18, ymid, chart.y.label,
              " text-anchor=\"middle\" transform=\"rotate(-90 18 " + px(ymid) + ")\"" +
                  axis_font(chart.y.label, 2 * std::min(ymid, chart.height - ymid) - 4))
      << "\n";
  svg << "<rect x=\"" << px(left) << "\" y=\"" << px(top) << "\" width=\"" << px(right - left)
      << "\" height=\"" << px(bottom - top) << "\" fill=\"none\" stroke=\"#333333\"/>\n";

  // 4. Reference lines, then series (lines and error bars clipped to the plot).
  svg << "<g clip-path=\"url(#" << id << "-plot)\">\n";
  for (const auto& h : chart.hlines) {
    if (!usable(h.y, chart.y.scale)) continue;
    svg << "<path d=\"M" << px(left) << " " << px(my(h.y)) << "H" << px(right) << "\" stroke=\""
        << palette_colour(h.colour) << "\" stroke-width=\"1.5\"" << (h.dashed ? " stroke-dasharray=\"7 4\"" : "")
        << " fill=\"none\"/>\n";
  }
  std::ostringstream points;
  // Markers, error bars and lines first, so that point labels avoid them too.
  LabelBoxes labels{{left, top, right, bottom}, {}, {}, {}};
  for (const auto& h : chart.hlines) {
    if (usable(h.y, chart.y.scale)) labels.lines.push_back({left, my(h.y), right, my(h.y)});
  }
  for (const auto& s : chart.series) {
    for (std::size_t i = 1; s.line && i < std::min(s.x.size(), s.y.size()); ++i) {
      if (usable(s.x[i - 1], chart.x.scale) && usable(s.y[i - 1], chart.y.scale) && usable(s.x[i], chart.x.scale) &&
          usable(s.y[i], chart.y.scale))
        labels.lines.push_back({mx(s.x[i - 1]), my(s.y[i - 1]), mx(s.x[i]), my(s.y[i])});
    }
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()) && s.marker != Marker::none; ++i) {
      if (!mx.contains(s.x[i]) || !my.contains(s.y[i])) continue;
      const double x = mx(s.x[i]), y = my(s.y[i]);
      labels.boxes.push_back({x - 5, y - 5, x + 5, y + 5});
      const double e = i < s.y_error.size() ? s.y_error[i] : NAN;
      if (std::isfinite(e) && e > 0) {
        const double lo = usable(s.y[i] - e, chart.y.scale) ? my(s.y[i] - e) : bottom;
        labels.boxes.push_back({x - 4.5, std::max(my(s.y[i] + e), top) - 1, x + 4.5, std::min(lo, bottom) + 1});
      }
    }
  }
  for (std::size_t si = 0; si < chart.series.size(); ++si) {
    const auto& s = chart.series[si];
    const std::string colour = palette_colour(s.colour >= 0 ? s.colour : int(si));
    const std::size_t n = std::min(s.x.size(), s.y.size());
    if (s.line) {
      std::string path;
      bool pen_down = false;
      for (std::size_t i = 0; i < n; ++i) {
        if (!usable(s.x[i], chart.x.scale) || !usable(s.y[i], chart.y.scale)) {
          pen_down = false;
          continue;
        }
        path += pen_down ? 'L' : 'M';
        path += px(mx(s.x[i]));
        path += ' ';
        path += px(my(s.y[i]));
        pen_down = true;
      }
      if (!path.empty()) {
        svg << "<path d=\"" << path << "\" stroke=\"" << colour << "\" stroke-width=\"1.8\" fill=\"none\""
            << (s.dashed ? " stroke-dasharray=\"6 4\"" : "") << (s.faded ? " stroke-opacity=\"0.35\"" : "")
            << "/>\n";
      }
    }
    for (std::size_t i = 0; i < n && i < s.y_error.size(); ++i) {
      const double e = s.y_error[i];
      if (!(std::isfinite(e) && e > 0) || !usable(s.x[i], chart.x.scale) || !usable(s.y[i], chart.y.scale)) continue;
      const double lo = usable(s.y[i] - e, chart.y.scale) ? my(s.y[i] - e) : bottom + 10;
      svg << svg_error_bar(mx(s.x[i]), lo, my(s.y[i] + e), colour) << "\n";
    }
    // Markers are drawn unclipped, after all lines, so nothing hides them.
    for (std::size_t i = 0; i < n && s.marker != Marker::none; ++i) {
      const double x = s.x[i], y = s.y[i];
      const bool no_value = std::isnan(y);
      if (mx.contains(x) && (no_value || my.contains(y))) {
        const std::string marker = svg_marker(s.marker, mx(x), no_value ? bottom : my(y), colour, s.hollow);
        points << (s.faded ? "<g opacity=\"0.35\">" + marker + "</g>" : marker) << "\n";
        if (i < s.point_labels.size() && !s.point_labels[i].empty() && !no_value) {
          const std::string label = point_label(labels, mx(x), my(y), s.point_labels[i], narrow ? font - 2 : 10.0);
          if (!label.empty())
            points << label << "\n";
          else
            unplaced.push_back(s.point_labels[i]);
        }
        continue;
      }
      const double cx = std::clamp(usable(x, chart.x.scale) ? mx(x) : left, left, right);
      const double cy = no_value ? bottom : std::clamp(usable(y, chart.y.scale) ? my(y) : bottom, top, bottom);
      const int dx = usable(x, chart.x.scale) && mx.contains(x) ? 0 : (usable(x, chart.x.scale) && x > xt.hi ? 1 : -1);
      const int dy = dx != 0 ? 0 : (usable(y, chart.y.scale) && y > yt.hi ? -1 : 1);
      points << svg_offscale_arrow(cx, cy, dx, dy, colour) << "\n";
    }
  }
  svg << "</g>\n" << points.str();

  // 5. Legend and note.
  if (!legend.empty()) {
    // Beside the plot, or (narrow) under the x label, one entry a line.
    const double lx = narrow ? 12 : right + 14;
    const double ly0 = narrow ? bottom + 46 + font + x_label_room : top + 10;
    const double step = narrow ? legend_step : 18.0;
    const std::size_t max_rows = narrow ? legend.size() : static_cast<std::size_t>((bottom - top) / 18.0);
    const std::size_t rows = legend.size() > max_rows ? max_rows - 1 : legend.size();
    svg << "<g>";
    for (std::size_t i = 0; i < rows; ++i) {
      const auto& e = legend[i];
      const double ly = ly0 + step * double(i);
      if (e.faded) svg << "<g opacity=\"0.45\">";
      if (e.line) {
        svg << "<path d=\"M" << px(lx) << " " << px(ly) << "h22\" stroke=\"" << e.colour
            << "\" stroke-width=\"1.8\"" << (e.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>";
      }
      svg << svg_marker(e.marker, lx + 11, ly, e.colour, e.hollow);
      svg << text(lx + 28, ly + 4, e.label);
      if (e.faded) svg << "</g>";
    }
    if (rows < legend.size()) {
      svg << text(lx, ly0 + step * double(rows) + 4, "... and " + std::to_string(legend.size() - rows) + " more");
    }
    svg << "</g>\n";
  }
  for (std::size_t i = 0; i < note_lines.size(); ++i)
    svg << text(narrow ? 12.0 : left, chart.height - 10 - note_step * double(note_lines.size() - 1 - i), note_lines[i],
                " fill=\"#444444\" font-size=\"" + format_g(note_font, 3) + "\"")
        << "\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace

std::string render_svg(const Chart& chart) {
  std::vector<std::string> unplaced;
  std::string svg = render_svg_once(chart, unplaced);
  if (unplaced.empty()) return svg;
  // No label is lost silently: the note names those without a free place.
  Chart noted = chart;
  std::string names;
  for (std::size_t i = 0; i < unplaced.size() && i < 4; ++i) names += (i ? ", " : "") + unplaced[i];
  if (unplaced.size() > 4) names += ", …";
  noted.note += (noted.note.empty() ? "" : " ") + std::to_string(unplaced.size()) +
                " point label(s) had no free place and are not drawn (" + names + ").";
  std::vector<std::string> again;
  return render_svg_once(noted, again);
}

std::string render_svg_file(const Chart& chart) {
  return kSvgDeclaration + render_svg(chart);
}

}  // namespace gridfree
