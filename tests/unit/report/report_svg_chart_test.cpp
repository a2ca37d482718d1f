// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the SVG chart writer: tick generation (values worked out by hand
// in the comments), log axes, escaping, well-formed output, and the
// conventions for points without a value or off scale.
#include <gtest/gtest.h>

#include <cmath>

#include "report/chart_axis.h"
#include "report/svg_chart.h"
#include "report/text_format.h"
#include "xml_check.h"

namespace gridfree {
namespace {

using test::count_of;
using test::xml_problem;

// Tick values are products of a step and an integer; 1e-9 relative covers
// the last-bit rounding of that product.
void expect_values(const std::vector<double>& actual, const std::vector<double>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(actual[i], expected[i], 1e-9 * std::max(1.0, std::abs(expected[i]))) << "tick " << i;
  }
}

TEST(SvgChartTicks, NiceStepIsOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_step(0.17), 0.2);
  EXPECT_DOUBLE_EQ(nice_step(0.2), 0.2);   // exact steps are kept
  EXPECT_DOUBLE_EQ(nice_step(3.0), 5.0);
  EXPECT_DOUBLE_EQ(nice_step(7.0), 10.0);
  EXPECT_DOUBLE_EQ(nice_step(1.1e-4), 2e-4);
  EXPECT_DOUBLE_EQ(nice_step(1e-4), 1e-4);
}

TEST(SvgChartTicks, LinearTicksCoverTheDataOnWholeSteps) {
  // span 1.05 over 5 intervals = 0.21 → step 0.5; 1158.25 → floor to 1158.0,
  // 1159.3 → ceil to 1159.5.
  AxisTicks t = linear_ticks(1158.25, 1159.3, 6);
  EXPECT_DOUBLE_EQ(t.step, 0.5);
  expect_values(t.major, {1158.0, 1158.5, 1159.0, 1159.5});
  EXPECT_DOUBLE_EQ(t.lo, 1158.0);
  EXPECT_DOUBLE_EQ(t.hi, 1159.5);
  // 3.3/6 = 0.55 → step 1.
  expect_values(linear_ticks(0, 3.3, 7).major, {0, 1, 2, 3, 4});
  // Symmetric range: 2/4 = 0.5; zero must come out exactly 0 (no "-0").
  t = linear_ticks(-1, 1, 5);
  expect_values(t.major, {-1, -0.5, 0, 0.5, 1});
  EXPECT_EQ(format_tick(t.major[2], t, AxisScale::linear), "0");
}

TEST(SvgChartTicks, DegenerateRangeIsWidenedAroundTheValue) {
  // 5 ± 5% = [4.75, 5.25]; 0.5/5 = 0.1 → ticks 4.7 … 5.3.
  const AxisTicks t = linear_ticks(5, 5, 6);
  EXPECT_LT(t.lo, 5);
  EXPECT_GT(t.hi, 5);
  EXPECT_DOUBLE_EQ(t.step, 0.1);
  EXPECT_EQ(t.major.size(), 7u);
  // Zero-valued data: widened by ±1.
  const AxisTicks z = linear_ticks(0, 0, 6);
  EXPECT_LE(z.lo, -1);
  EXPECT_GE(z.hi, 1);
}

TEST(SvgChartTicks, LogTicksAreDecadesWithMinorTicksBetween) {
  // 0.003 … 0.4 → decades 1e-3 … 1e0; 3 decades, 8 minor ticks each.
  AxisTicks t = log_ticks(0.003, 0.4);
  expect_values(t.major, {1e-3, 1e-2, 1e-1, 1});
  EXPECT_EQ(t.minor.size(), 24u);
  EXPECT_DOUBLE_EQ(t.lo, 1e-3);
  EXPECT_DOUBLE_EQ(t.hi, 1.0);
  // Two decades or fewer: 1, 2, 5 per decade are labelled.
  t = log_ticks(2, 50);
  expect_values(t.major, {1, 2, 5, 10, 20, 50, 100});
  EXPECT_EQ(t.minor.size(), 12u);  // 3,4,6,7,8,9 in each of two decades
  // Twelve decades: every second decade labelled.
  t = log_ticks(1e-8, 1e4);
  expect_values(t.major, {1e-8, 1e-6, 1e-4, 1e-2, 1, 1e2, 1e4});
  // Data inside one decade still gets a whole decade.
  t = log_ticks(3, 4);
  EXPECT_DOUBLE_EQ(t.lo, 1);
  EXPECT_DOUBLE_EQ(t.hi, 10);
}

TEST(SvgChartTicks, TickLabels) {
  const AxisTicks lin = linear_ticks(1158.25, 1159.3, 6);
  EXPECT_EQ(format_tick(1158.5, lin, AxisScale::linear), "1158.5");
  EXPECT_EQ(format_tick(1159.0, lin, AxisScale::linear), "1159.0");
  // Axes reaching 10⁵: m×10ᵏ with the axis' exponent. 0 … 3.4e6 in about
  // 6 ticks: raw step 6.8e5 → 1e6, ticks 0 … 4e6.
  const AxisTicks big = linear_ticks(0, 3.4e6, 6);
  EXPECT_DOUBLE_EQ(big.step, 1e6);
  EXPECT_EQ(format_tick(4e6, big, AxisScale::linear), "4×10⁶");
  const AxisTicks half = linear_ticks(0, 1.8e6, 5);  // raw 4.5e5 → step 5e5
  EXPECT_EQ(format_tick(1.5e6, half, AxisScale::linear), "1.5×10⁶");
  EXPECT_EQ(format_tick(0, big, AxisScale::linear), "0");
  const AxisTicks lg = log_ticks(1e-6, 1e5);
  EXPECT_EQ(format_tick(1e-5, lg, AxisScale::log), "10⁻⁵");
  EXPECT_EQ(format_tick(1e4, lg, AxisScale::log), "10⁴");
  EXPECT_EQ(format_tick(0.01, lg, AxisScale::log), "0.01");
  EXPECT_EQ(format_tick(100, lg, AxisScale::log), "100");
  EXPECT_EQ(format_tick(1000, lg, AxisScale::log), "1000");
  EXPECT_EQ(format_tick(2000, lg, AxisScale::log), "2000");
  EXPECT_EQ(format_tick(2e-4, lg, AxisScale::log), "0.0002");
  EXPECT_EQ(format_tick(2e5, lg, AxisScale::log), "2×10⁵");
  EXPECT_EQ(format_tick(5e-7, lg, AxisScale::log), "5×10⁻⁷");
}

TEST(SvgChartTicks, AxisMapIsLinearInValueOrInLogValue) {
  const AxisMap lin{AxisScale::linear, 0, 10, 100, 600};
  EXPECT_DOUBLE_EQ(lin(5), 350);
  const AxisMap lg{AxisScale::log, 1, 1000, 400, 100};  // y axis: pixels decrease upwards
  EXPECT_NEAR(lg(10), 300, 1e-9);
  EXPECT_NEAR(lg(100), 200, 1e-9);
  EXPECT_FALSE(lg.contains(0.0));
  EXPECT_FALSE(lg.contains(2000.0));
  EXPECT_TRUE(lg.contains(1000.0));
}

Chart sample_chart() {
  Chart c;
  c.id = "sample";
  c.title = "DP* <vs> Δ* & friends";
  c.subtitle = "fit \"power\" 'quoted'";
  c.x = {"Δ*", AxisScale::linear, 0.0, std::nullopt};
  c.y = {"DP*", AxisScale::linear, std::nullopt, std::nullopt};
  c.series.push_back({"data <1>", {0.5, 1.0, 2.0}, {1158.9, 1158.6, 1159.2}, {0.3, 0.2, 0.5},
                      Marker::circle, false, false, false, 0});
  c.series.push_back({"fit & more", {0, 1, 2}, {1158.8, 1158.9, 1159.0}, {}, Marker::none, true, true, false, 2});
  c.series.push_back({"failed", {3.0}, {NAN}, {}, Marker::x_mark, false, false, false, 1});
  c.hlines.push_back({1158.8, "f0 = 1158.8", 6, true});
  return c;
}

TEST(SvgChartRender, IsWellFormedAndEscapesText) {
  const std::string svg = render_svg_file(sample_chart());
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_NE(svg.find("DP* &lt;vs&gt; Δ* &amp; friends"), std::string::npos);
  EXPECT_NE(svg.find("fit &quot;power&quot; &#39;quoted&#39;"), std::string::npos);
  EXPECT_NE(svg.find("data &lt;1&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("<vs>"), std::string::npos);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("width=\"720\" height=\"450\""), std::string::npos);
}

TEST(SvgChartRender, IsDeterministicAndSelfContained) {
  const std::string a = render_svg(sample_chart());
  EXPECT_EQ(a, render_svg(sample_chart()));
  EXPECT_EQ(count_of(a, "http"), 1);  // only the SVG namespace
  EXPECT_EQ(count_of(a, "href"), 0);
  EXPECT_EQ(count_of(a, "<script"), 0);
  EXPECT_EQ(count_of(a, "<image"), 0);
}

TEST(SvgChartRender, ClipPathIdsFollowTheChartId) {
  Chart a = sample_chart(), b = sample_chart();
  b.id = "other";
  EXPECT_NE(render_svg(a).find("id=\"sample-plot\""), std::string::npos);
  EXPECT_NE(render_svg(b).find("id=\"other-plot\""), std::string::npos);
}

TEST(SvgChartRender, PointWithoutValueSitsOnTheBottomEdge) {
  Chart c;
  c.id = "nan";
  c.series.push_back({"", {1, 2, 3}, {1, NAN, 2}, {}, Marker::circle, true, false, false, 0});
  const std::string svg = render_svg(c);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count_of(svg, "<circle"), 3);  // unnamed series: no legend marker
  // Plot bottom = height − 66 = 384 px (svg_chart.cpp layout).
  EXPECT_NE(svg.find("cy=\"384.00\""), std::string::npos);
  // The line breaks at the missing value: one path of two single-point
  // sub-paths (two "M" moves, no "L" segment).
  const std::size_t at = svg.find("<path d=\"M", svg.find("clip-path=\"url(#nan-plot)\""));
  const std::string d = svg.substr(at, svg.find('"', at + 9) - at);
  EXPECT_EQ(count_of(d, "M"), 2) << d;
  EXPECT_EQ(count_of(d, "L"), 0) << d;
}

TEST(SvgChartRender, ErrorBarsWidenTheRange) {
  Chart c;
  c.id = "err";
  c.series.push_back({"", {1}, {5}, {10}, Marker::square, false, false, false, 0});
  const std::string svg = render_svg(c);
  // y range must hold 5 ± 10 = [−5, 15]: step 5, labels −5 … 15.
  EXPECT_NE(svg.find(">15</text>"), std::string::npos);
  EXPECT_NE(svg.find(">-5</text>"), std::string::npos);
  EXPECT_EQ(count_of(svg, "<rect x="), 3);  // clip rect, marker, frame
}

TEST(SvgChartRender, OffScalePointsBecomeArrowsAndAreCounted) {
  Chart c;
  c.id = "off";
  c.y.min = 0.0;
  c.y.max = 10.0;
  c.series.push_back({"", {1, 2, 3}, {5, 100, -50}, {}, Marker::circle, false, false, false, 0});
  const std::string svg = render_svg(c);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_EQ(count_of(svg, "<circle"), 1);
  EXPECT_NE(svg.find("2 points off scale"), std::string::npos);
}

TEST(SvgChartRender, LogLogChartDropsNothing) {
  Chart c;
  c.id = "loglog";
  c.x = {"error", AxisScale::log, std::nullopt, std::nullopt};
  c.y = {"CPU s", AxisScale::log, std::nullopt, std::nullopt};
  c.series.push_back({"s", {1e-4, 1e-3, 0.0}, {100, 10, 1}, {}, Marker::diamond, true, false, false, 0});
  const std::string svg = render_svg(c);
  EXPECT_EQ(xml_problem(svg), "");
  // Two diamonds in the plot + one in the legend; the zero error is an arrow.
  EXPECT_EQ(count_of(svg, "<polygon"), 3 + 1);
  EXPECT_NE(svg.find("1 point off scale"), std::string::npos);
  EXPECT_NE(svg.find(">0.0001</text>"), std::string::npos);
}

TEST(SvgChartRender, EmptyChartStillRenders) {
  Chart c;
  c.title = "nothing yet";
  const std::string svg = render_svg(c);
  EXPECT_EQ(xml_problem(svg), "");
  EXPECT_NE(svg.find("nothing yet"), std::string::npos);
}

TEST(ReportTextFormat, EscapesAndNumbers) {
  EXPECT_EQ(xml_escape("<a & 'b'>"), "&lt;a &amp; &#39;b&#39;&gt;");
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(md_cell("a|b\nc"), "a\\|b c");
  EXPECT_EQ(format_exact(0.1), "0.1");  // shortest text that reads back exactly
  EXPECT_EQ(std::strtod(format_exact(1158.8012345678901).c_str(), nullptr), 1158.8012345678901);
  EXPECT_EQ(format_g(1158.8, 6), "1158.8");
  EXPECT_EQ(format_percent(0.01234), "1.23%");
  EXPECT_EQ(format_percent(std::nullopt), "");
  EXPECT_EQ(slugify("PC1 superbee fwhm6 bvk"), "PC1_superbee_fwhm6_bvk");
}

// f0 ± U: U to two significant digits, f0 to U's last digit.
TEST(ReportText, ValueRoundedToTheDigitsItsUncertaintySupports) {
  EXPECT_EQ(format_with_uncertainty(1010.7944, 12.712), "1011 ± 13");
  EXPECT_EQ(format_with_uncertainty(1017.3920, 1.37), "1017.4 ± 1.4");
  EXPECT_EQ(format_with_uncertainty(1158.8123, 0.0123), "1158.812 ± 0.012");
  EXPECT_EQ(format_with_uncertainty(123456.0, 1234.0), "123500 ± 1200");
  EXPECT_EQ(format_with_uncertainty(1158.8, std::nullopt), "1158.8");
  EXPECT_EQ(format_with_uncertainty(1158.8, 0.0), "1158.8 ± 0");  // said, never "± 0.000"
}

}  // namespace
}  // namespace gridfree
