// SPDX-License-Identifier: GPL-3.0-or-later
// Layout of the report on screen and in print: no chart text outside its
// SVG's box (long titles, subtitles, notes, legends and tick labels),
// point labels that never overlap each other or a marker, every section of
// the page in its table of contents, and each table's print layout chosen
// from its narrowest width. Text boxes are estimated (svg_text_boxes.h);
// the rendered check is the integration test report_render_test.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

#include "report/chart_pareto.h"
#include "report/chart_series.h"
#include "report/extrapolator.h"
#include "report/html_toc.h"
#include "report/report.h"
#include "report/series_summary.h"
#include "report/svg_chart.h"
#include "report/svg_text.h"
#include "report/table_print_fit.h"
#include "report_test_data.h"
#include "svg_text_boxes.h"
#include "test_files.h"
#include "xml_check.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += i + "\n";
  return out;
}

// The demo's two series on its grids Δ* 2 … 0.667: 0.786 and 0.667 are
// 0.119 apart (about 20 px on the chart), their values 0.1 apart; the
// second series (fou) costs 0.6 times as much, so on the speed-vs-accuracy
// chart its front runs just under the first's.
StudyReportData close_grids_study() {
  StudyReportData d;
  d.study_name = "close grids";
  d.status = "done";
  for (const char* scheme : {"superbee", "fou"}) {
    const double cost = scheme[0] == 's' ? 1.0 : 0.6;
    SeriesData s{scheme[0] == 's' ? 1 : 2, "PC1", scheme, "bvk", "diffusion", 6, "done", {}, {}};
    for (double h : {2.0, 1.5, 1.0, 0.786, 0.667}) {
      GridPoint g;
      g.delta_star = h;
      g.nx = static_cast<int>(std::lround(30 / h));
      g.ny = static_cast<int>(std::lround(200 / h));
      g.nz = static_cast<int>(std::lround(10 / h));
      g.status = "converged";
      g.dp_star = 1016.995 - 2.3 * std::pow(h, 1.6) + 0.01 * std::sin(7 * h);
      g.iterations = 200;
      g.cpu_s = cost * 10 / (h * h * h);
      g.wall_s = g.cpu_s / 2;
      s.grids.push_back(g);
    }
    d.series.push_back(s);
  }
  return d;
}

TEST(ReportPrintLayout, WrappedMarkupKeepsWordsAndScriptsWhole) {
  const auto lines = wrap_markup("f_{0} = 1016.995 and σ_{RE}/R_{f} = 0.3 (good fit)", 80, 12);
  ASSERT_GT(lines.size(), 2u);
  std::string back;
  for (const auto& l : lines) {
    EXPECT_TRUE(l.size() < 12 || text_width_px(l, 12) <= 80) << l;
    back += (back.empty() ? "" : " ") + l;
  }
  EXPECT_EQ(back, "f_{0} = 1016.995 and σ_{RE}/R_{f} = 0.3 (good fit)");
  EXPECT_EQ(wrap_markup("a_{x y} b", 1, 12), (std::vector<std::string>{"a_{x y}", "b"}));  // never inside a script
  EXPECT_TRUE(wrap_markup("", 100, 12).empty());
}

// Long title, subtitle, note and axis labels, no legend, tick labels at
// the right edge: every text inside the viewBox, no two texts overlapping,
// none of it dropped.
TEST(ReportPrintLayout, LongChartTextStaysInsideTheSvg) {
  Chart c;
  c.id = "long";
  c.title = "What a target costs: CPU time against RDE for every series of a study with a very long name indeed";
  c.subtitle = "each converged grid at its a-priori RDE = U_{i}/|f_{0}|; the Pareto front of each converged series "
               "connected, dominated grids faded; series not converged hollow and never on a front";
  c.note = "For a target RDE, the cheapest grid is the lowest front point left of it whose finer grids are all left "
           "of it too (table \"What a target costs\").";
  c.x = {"RDE (a priori, %) of every grid of every series, estimated before the finest grid is known", AxisScale::linear,
         0.0, 100.0};
  c.x.tick_suffix = "%";
  c.y = {"cells × outer iterations", AxisScale::linear, std::nullopt, std::nullopt};
  c.y.tick_suffix = " cells·its";
  c.series.push_back({"", {0, 50, 100}, {1.5e6, 2.5e6, 1.2345e7}, {}, Marker::circle, true, false, false, 0});
  const std::string svg = render_svg(c);
  EXPECT_EQ(test::xml_problem(svg), "");
  EXPECT_EQ(joined(test::texts_outside_view_box(svg)), "");
  EXPECT_EQ(joined(test::overlapping_texts(svg)), "");
  std::string all_text;
  for (const auto& b : test::svg_text_boxes(svg)) all_text += b.text + " ";
  for (const char* word : {"(table", "\"What a target costs\").", "front", "indeed", "100%"})
    EXPECT_NE(all_text.find(xml_escape(word)), std::string::npos) << word;
  // The plot keeps its height: the chart grew by the extra lines.
  EXPECT_GT(test::svg_view_box(svg).second, 450);
}

// Every chart of a report on the synthetic study (speed-vs-accuracy with
// its long subtitle and footnote, Fig. 1 with its legend, GCI, RDE…): text
// inside the box, no two texts overlapping.
TEST(ReportPrintLayout, EveryReportChartKeepsItsTextInside) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("gridfree-print-layout-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const ReportFiles files = write_study_report(test::synthetic_study(), dir, test::fake_extrapolation);
  ASSERT_GE(files.svg.size(), 5u);
  for (const auto& svg_file : files.svg) {
    const std::string svg = test_support::slurp(svg_file);
    EXPECT_EQ(joined(test::texts_outside_view_box(svg)), "") << svg_file;
    EXPECT_EQ(joined(test::overlapping_texts(svg)), "") << svg_file;
  }
  fs::remove_all(dir);
}

// No two point labels overlap, none covers a marker and no series line or
// fit curve crosses one: hand-made points 0.667 / 0.786 / 0.7 at nearly
// the same value, Fig. 1 of a series on the demo's grids with the
// library's extrapolation (error bars, fit curves, legend), and the
// speed-vs-accuracy chart of the same series (front connected by a line).
TEST(ReportPrintLayout, PointLabelsNeitherOverlapNorCoverAPoint) {
  Chart hand;
  hand.id = "labels";
  hand.x = {"Δ*", AxisScale::linear, 0.0, 3.0};
  hand.y = {"DP*", AxisScale::linear, 1000.0, 1020.0};
  ChartSeries s{"", {0.667, 0.786, 0.70}, {1015.86, 1015.66, 1015.8}, {}, Marker::circle, false, false, false, 0};
  s.point_labels = {"0.667", "0.786", "0.7"};
  hand.series.push_back(s);
  const auto summaries = summarize_series(close_grids_study(), library_extrapolator(ExtrapolatorSettings{}));
  ASSERT_EQ(summaries.size(), 2u);
  const Chart fig1 = series_chart(summaries[0], 0);
  ASSERT_EQ(fig1.series[0].point_labels.size(), 5u);
  const Chart pareto = speed_accuracy_chart(summaries, CostMeasure::cpu_seconds);
  for (const Chart* chart : std::initializer_list<const Chart*>{&hand, &fig1, &pareto}) {
    const std::string svg = render_svg(*chart);
    std::vector<test::TextBox> labels;
    for (const auto& b : test::svg_text_boxes(svg))
      if (b.cls == "point-label") labels.push_back(b);
    EXPECT_GE(labels.size(), chart == &hand ? 2u : 3u) << svg;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      for (std::size_t j = i + 1; j < labels.size(); ++j)
        EXPECT_FALSE(labels[i].overlaps(labels[j])) << labels[i].text << " overlaps " << labels[j].text;
      for (const auto& [cx, cy] : test::svg_circles(svg))
        EXPECT_FALSE(labels[i].overlaps({cx - 4, cy - 4, cx + 4, cy + 4, "", ""}))
            << labels[i].text << " covers the marker at " << cx << ", " << cy;
      for (const auto& line : test::svg_polyline_segments(svg))
        EXPECT_FALSE(test::crosses(line, labels[i]))
            << labels[i].text << " is crossed by a line from " << line.xa << ", " << line.ya;
    }
    EXPECT_EQ(joined(test::texts_outside_view_box(svg)), "");
    EXPECT_EQ(joined(test::overlapping_texts(svg)), "");
  }
}

// The contents list every section of the page (h2 and h3 with an id) and
// nothing else: with adaptive decisions and an "about this case" section.
TEST(ReportPrintLayout, ContentsListEverySection) {
  StudyReportData d = test::synthetic_study();
  d.adaptive_decisions = {"series 1: added Δ* 0.5 (RDE 2 % above the target 1 %)"};
  d.generator_kinds = {"bursting_bubble"};
  const fs::path dir = fs::path(::testing::TempDir()) / ("gridfree-toc-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const ReportFiles files = write_study_report(d, dir, test::fake_extrapolation);
  const std::string html = test_support::slurp(files.html);
  fs::remove_all(dir);
  EXPECT_EQ(test::xml_problem(html, true), "");
  const auto nav_at = html.find("<nav class=\"toc\">"), nav_end = html.find("</nav>");
  ASSERT_NE(nav_at, std::string::npos);
  const std::string nav = html.substr(nav_at, nav_end - nav_at);
  const std::string page = html.substr(nav_end);
  std::set<std::string> ids;
  const std::regex heading("<h([23]) id=\"([^\"]+)\">");
  for (auto it = std::sregex_iterator(page.begin(), page.end(), heading); it != std::sregex_iterator(); ++it) {
    EXPECT_TRUE(ids.insert((*it)[2]).second) << "duplicate id " << (*it)[2];
    EXPECT_NE(nav.find("href=\"#" + (*it)[2].str() + "\""), std::string::npos) << "not in the contents: " << (*it)[2];
  }
  for (const char* id : {"verdicts", "adaptive", "about", "series", "charts", "per-series", "grids"})
    EXPECT_EQ(ids.count(id), 1u) << id;
  EXPECT_NE(nav.find(">Adaptive grids</a>"), std::string::npos);
  const std::regex link("href=\"#([^\"]+)\"");
  for (auto it = std::sregex_iterator(nav.begin(), nav.end(), link); it != std::sregex_iterator(); ++it)
    EXPECT_EQ(ids.count((*it)[1]), 1u) << "contents link to no section: " << (*it)[1];
}

TEST(ReportPrintLayout, ContentsNestSubsections) {
  const auto sections = html_sections("<h2 id=\"a\">A &amp; b</h2><p>x</p><h3 id=\"b\">B <em>c</em></h3>"
                                      "<h3>no id</h3><h3 id=\"c\">C</h3><h2 id=\"d\">D</h2><header id=\"x\"></header>");
  ASSERT_EQ(sections.size(), 4u);
  EXPECT_EQ(sections[1].title_html, "B c");
  EXPECT_EQ(toc_list_html(sections),
            "<ul>\n<li><a href=\"#a\">A &amp; b</a><ul>\n<li><a href=\"#b\">B c</a></li>\n"
            "<li><a href=\"#c\">C</a></li>\n</ul></li>\n<li><a href=\"#d\">D</a></li>\n</ul>\n");
  EXPECT_EQ(test::xml_problem(toc_list_html(sections), true), "");
}

// Narrowest print width: 190 mm = 538.6 pt holds a portrait table; numbers
// count whole, text by its longest word. A column of "1016.995 ± 4.2"
// (14 characters) at 6.5 pt is 14 × 0.62 × 6.5 = 56.4 pt + 3.75 pt padding:
// 8 such columns (482 pt) fit portrait, 12 (722 pt) need landscape
// (277 mm = 785 pt), 16 (963 pt) the small landscape font.
TEST(ReportPrintLayout, TablesPrintPortraitLandscapeOrSmall) {
  auto table = [](int columns) {
    Table t;
    for (int c = 0; c < columns; ++c) t.columns.push_back({"c" + std::to_string(c), "", false, true, false});
    t.rows.push_back({});
    for (int c = 0; c < columns; ++c) t.rows[0].push_back({"", "1016.995 ± 4.2"});
    return t;
  };
  EXPECT_NEAR(narrowest_print_width_pt(table(8), 6.5), 8 * (14 * 0.62 * 6.5 + 3.75), 1e-9);
  EXPECT_EQ(print_fit_class(table(8)), "fit-portrait");
  EXPECT_EQ(print_fit_class(table(12)), "fit-landscape");
  EXPECT_EQ(print_fit_class(table(16)), "fit-landscape-small");
  // The same text in a text column breaks at its spaces: 8 characters wide.
  Table words = table(16);
  for (auto& c : words.columns) c.numeric = false;
  EXPECT_NEAR(narrowest_print_width_pt(words, 6.5), 16 * (8 * 0.62 * 6.5 + 3.75), 1e-9);
  EXPECT_NE(to_html(table(12)).find("<table class=\"data fit-landscape\">"), std::string::npos);
  // Small landscape lets a number cell break at its spaces (never inside a
  // number): "1016.995" is 8 characters, 8 × 0.62 × 5 + 3.75 = 28.55 pt a
  // column, so 27 columns (771 pt) still fit 785 pt, 28 (799 pt) do not.
  EXPECT_NEAR(narrowest_print_width_pt(table(27), 5, true), 27 * (8 * 0.62 * 5 + 3.75), 1e-9);
  EXPECT_LT(narrowest_print_width_pt(table(27), 5, true), 277 * 72 / 25.4);
  EXPECT_GT(narrowest_print_width_pt(table(28), 5, true), 277 * 72 / 25.4);
}

}  // namespace
}  // namespace gridfree
