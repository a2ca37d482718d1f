// SPDX-License-Identifier: GPL-3.0-or-later
// Estimated boxes of an SVG's <text> elements, for the report's layout
// tests: "does every text lie inside the viewBox", "do two labels overlap".
// Width ≈ 0.6 × font-size per character (DejaVu Sans averages 0.6–0.64 em;
// bold counted 10 % wider), a <tspan font-size="75%"> script at 75 %;
// height from 0.8 em above the baseline to 0.25 em below. text-anchor and
// a transform="rotate(-90 cx cy)" (the y-axis label) are honoured.
#pragma once

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

namespace gridfree::test {

struct TextBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::string text;   // content without tags
  std::string cls;    // the class attribute
  bool overlaps(const TextBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

inline std::string svg_attribute(const std::string& tag, const std::string& name) {
  std::smatch m;
  if (std::regex_search(tag, m, std::regex("\\s" + name + "=\"([^\"]*)\""))) return m[1];
  return {};
}

// Code points, with the five XML entities counted as one character.
inline double svg_chars(const std::string& escaped) {
  double n = 0;
  for (std::size_t i = 0; i < escaped.size(); ++i) {
    const auto ch = static_cast<unsigned char>(escaped[i]);
    if (ch == '&') {
      const auto semi = escaped.find(';', i);
      if (semi != std::string::npos) i = semi;
    }
    if ((ch & 0xC0) != 0x80) n += 1;
  }
  return n;
}

inline std::vector<TextBox> svg_text_boxes(const std::string& svg) {
  const std::size_t root_at = svg.find("<svg");
  const std::string root = svg.substr(root_at, svg.find('>', root_at) - root_at);
  const double root_font = std::stod(svg_attribute(root, "font-size").empty() ? "16" : svg_attribute(root, "font-size"));
  std::vector<TextBox> out;
  const std::regex text_re("<text([^>]*)>([\\s\\S]*?)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text_re); it != std::sregex_iterator(); ++it) {
    const std::string attrs = " " + (*it)[1].str(), content = (*it)[2];
    const std::string fs = svg_attribute(attrs, "font-size");
    const double font = fs.empty() ? root_font : std::stod(fs);
    // Content: plain runs at full size, tspans with font-size="75%" at 75 %.
    double chars = 0;
    std::string plain;
    const std::regex tspan_re("<tspan[^>]*>([^<]*)</tspan>");
    std::size_t last = 0;
    for (auto t = std::sregex_iterator(content.begin(), content.end(), tspan_re); t != std::sregex_iterator(); ++t) {
      const std::string before = content.substr(last, static_cast<std::size_t>(t->position()) - last);
      chars += svg_chars(before) + 0.75 * svg_chars((*t)[1]);
      plain += before + (*t)[1].str();
      last = static_cast<std::size_t>(t->position() + t->length());
    }
    chars += svg_chars(content.substr(last));
    plain += content.substr(last);
    const double bold = svg_attribute(attrs, "font-weight") == "bold" ? 1.1 : 1.0;
    const double w = 0.6 * font * chars * bold;
    const double x = std::stod(svg_attribute(attrs, "x")), y = std::stod(svg_attribute(attrs, "y"));
    const std::string anchor = svg_attribute(attrs, "text-anchor");
    TextBox b;
    b.x0 = anchor == "middle" ? x - w / 2 : anchor == "end" ? x - w : x;
    b.x1 = b.x0 + w;
    b.y0 = y - 0.8 * font;
    b.y1 = y + 0.25 * font;
    std::smatch rot;
    const std::string transform = svg_attribute(attrs, "transform");
    if (std::regex_search(transform, rot, std::regex("rotate\\(-90 ([-0-9.]+) ([-0-9.]+)\\)"))) {
      // (px, py) → (cx + (py − cy), cy − (px − cx)).
      const double cx = std::stod(rot[1]), cy = std::stod(rot[2]);
      const TextBox r = b;
      b.x0 = cx + (r.y0 - cy);
      b.x1 = cx + (r.y1 - cy);
      b.y0 = cy - (r.x1 - cx);
      b.y1 = cy - (r.x0 - cx);
    }
    b.text = plain;
    b.cls = svg_attribute(attrs, "class");
    out.push_back(b);
  }
  return out;
}

// Width and height of the svg's viewBox "0 0 W H".
inline std::pair<double, double> svg_view_box(const std::string& svg) {
  std::smatch m;
  if (!std::regex_search(svg, m, std::regex("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\""))) return {0, 0};
  return {std::stod(m[1]), std::stod(m[2])};
}

// Every text whose box leaves the viewBox (0.5 px tolerance), described.
inline std::vector<std::string> texts_outside_view_box(const std::string& svg) {
  const auto [w, h] = svg_view_box(svg);
  std::vector<std::string> out;
  for (const TextBox& b : svg_text_boxes(svg)) {
    if (b.x0 < -0.5 || b.y0 < -0.5 || b.x1 > w + 0.5 || b.y1 > h + 0.5)
      out.push_back("\"" + b.text + "\" at [" + std::to_string(b.x0) + ", " + std::to_string(b.x1) + "] × [" +
                    std::to_string(b.y0) + ", " + std::to_string(b.y1) + "] in " + std::to_string(w) + " × " +
                    std::to_string(h));
  }
  return out;
}

// Every pair of texts whose boxes overlap, described.
inline std::vector<std::string> overlapping_texts(const std::string& svg) {
  const auto boxes = svg_text_boxes(svg);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) out.push_back("\"" + boxes[i].text + "\" overlaps \"" + boxes[j].text + "\"");
  return out;
}

// Centres of the circle markers (<circle cx cy r>).
inline std::vector<std::pair<double, double>> svg_circles(const std::string& svg) {
  std::vector<std::pair<double, double>> out;
  const std::regex re("<circle cx=\"([-0-9.]+)\" cy=\"([-0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator(); ++it)
    out.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  return out;
}

// Segments of the drawn polylines (<path d="M x y L x y …"/>: series and
// fit curves; grid lines, ticks and error bars use H/V and are left out).
struct Segment {
  double xa, ya, xb, yb;
};
inline std::vector<Segment> svg_polyline_segments(const std::string& svg) {
  std::vector<Segment> out;
  const std::regex path_re("<path d=\"(M[-0-9. ]+(?:L[-0-9. ]+)+)\"");
  const std::regex point_re("([ML])([-0-9.]+) ([-0-9.]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path_re); it != std::sregex_iterator(); ++it) {
    const std::string d = (*it)[1];
    bool have = false;
    double px = 0, py = 0;
    for (auto p = std::sregex_iterator(d.begin(), d.end(), point_re); p != std::sregex_iterator(); ++p) {
      const double x = std::stod((*p)[2]), y = std::stod((*p)[3]);
      if ((*p)[1] == "L" && have) out.push_back({px, py, x, y});
      px = x, py = y, have = true;
    }
  }
  return out;
}

// Whether the segment passes through the box's interior (sampled every 0.25 px).
inline bool crosses(const Segment& s, const TextBox& b) {
  const double len = std::hypot(s.xb - s.xa, s.yb - s.ya);
  const int n = std::max(1, static_cast<int>(len * 4));
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n, x = s.xa + t * (s.xb - s.xa), y = s.ya + t * (s.yb - s.ya);
    if (x > b.x0 && x < b.x1 && y > b.y0 && y < b.y1) return true;
  }
  return false;
}

}  // namespace gridfree::test
