// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the report's chart rules: the log-axis rule, sub/superscript
// markup, legends sized to their text, point labels that do not collide,
// f0 ± U rounding in the charts, GCI bands by convergence type, the Pareto
// front of cost against RDE and the "what a target costs" table. Expected
// values are worked out by hand (comments) or recomputed here from the
// manufactured data of report_test_data.h, never read back from the code.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>

#include "report/chart_axis.h"
#include "report/cost_table.h"
#include "report/report_charts.h"
#include "report/series_summary.h"
#include "report/svg_chart.h"
#include "report/svg_text.h"
#include "report/text_format.h"
#include "report_test_data.h"
#include "xml_check.h"

namespace gridfree {
namespace {

int svg_width(const std::string& svg) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(svg, m, std::regex("<svg [^>]*width=\"([0-9]+)\"")));
  return m.empty() ? 0 : std::stoi(m[1]);
}

// Log when positive data span more than a decade (hi/lo > 10), else linear.
TEST(ChartRules, LogAxisWhenTheDataSpanMoreThanADecade) {
  EXPECT_EQ(scale_for_span(0.5, 4.0), AxisScale::linear);
  EXPECT_EQ(scale_for_span(0.5, 5.0), AxisScale::linear);  // exactly one decade
  EXPECT_EQ(scale_for_span(0.5, 5.01), AxisScale::log);
  EXPECT_EQ(scale_for_span(5.01, 0.5), AxisScale::log);   // order does not matter
  EXPECT_EQ(scale_for_span(0.0, 100.0), AxisScale::linear);  // zero cannot sit on a log axis
  EXPECT_EQ(scale_for_span(-1.0, 100.0), AxisScale::linear);
}

// RDE 0.15 … 8 %: log axis with 1-2-5 labels and a % suffix; RDE 1 … 8 %
// stays linear (0, 2, 4, 6, 8 %).
TEST(ChartRules, AutoLogAxisHasReadableTicks) {
  Chart c;
  c.id = "rde";
  c.x = {"Δ*", AxisScale::linear, 0.0, std::nullopt};
  c.y = {"RDE (%)", AxisScale::linear, 0.0, std::nullopt};
  c.y.auto_log = true;
  c.y.tick_suffix = "%";
  c.series.push_back({"s", {0.5, 1, 2}, {0.15, 1.2, 8.0}, {}, Marker::circle, true, false, false, 0});
  std::string svg = render_svg(c);
  for (const char* tick : {">0.2%</text>", ">0.5%</text>", ">1%</text>", ">2%</text>", ">5%</text>"})
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  c.series[0].y = {1.0, 4.0, 8.0};
  svg = render_svg(c);
  EXPECT_NE(svg.find(">4%</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">0.5%</text>"), std::string::npos);
}

TEST(ChartRules, SubscriptsAreTspansWithBaselineShift) {
  EXPECT_EQ(svg_rich_text("σ_{RE}/R_{f}"),
            "σ<tspan baseline-shift=\"sub\" font-size=\"75%\">RE</tspan>/R"
            "<tspan baseline-shift=\"sub\" font-size=\"75%\">f</tspan>");
  EXPECT_EQ(svg_rich_text("h^{p} & <x>"), "h<tspan baseline-shift=\"super\" font-size=\"75%\">p</tspan> &amp; &lt;x&gt;");
  EXPECT_EQ(svg_rich_text("f_i plain"), "f_i plain");  // no braces: not markup
  EXPECT_EQ(plain_text("f_{0} = 1017.0 ± 1.5"), "f0 = 1017.0 ± 1.5");
  // A script counts at 75 %: "f_{0}" is 1.75 characters wide.
  EXPECT_DOUBLE_EQ(text_width_px("f_{0}", 10.0), text_width_px("f", 10.0) * 1.75);
}

// A 70-character legend entry is written whole, and the chart grows so that
// the entry ends inside it.
TEST(ChartRules, LegendSizesToItsLongestEntry) {
  const std::string long_name =
      "PC1 superbee fwhm6 gidaspow_blend gaussian_exact (incomplete) (rejected)";
  Chart c;
  c.id = "legend";
  c.series.push_back({long_name, {1, 2}, {3, 4}, {}, Marker::circle, true, false, false, 0});
  const std::string svg = render_svg(c);
  EXPECT_EQ(test::xml_problem(svg), "");
  EXPECT_NE(svg.find(">" + long_name + "</text>"), std::string::npos);
  EXPECT_EQ(svg.find("..."), std::string::npos);
  const double entry_w = text_width_px(long_name, 12.0);
  EXPECT_GT(entry_w, 280.0);  // longer than the default legend column
  // Legend text starts 28 px into the column, the column ends 16 px before the edge.
  EXPECT_GE(svg_width(svg), 720 + static_cast<int>(entry_w + 44 - 280));
  Chart short_legend = c;
  short_legend.series[0].name = "a";
  EXPECT_EQ(svg_width(render_svg(short_legend)), 720);
}

// Points 0.667 and 0.786 at nearly the same value: the second label moves
// to the other side of its point; a third label colliding on both sides is
// moved out with a leader line.
TEST(ChartRules, PointLabelsDoNotOverlap) {
  Chart c;
  c.id = "labels";
  c.x = {"Δ*", AxisScale::linear, 0.0, 3.0};  // 0.119 Δ* ≈ 25 px: labels ~31 px wide collide
  c.y = {"DP*", AxisScale::linear, 1000.0, 1020.0};
  ChartSeries s{"", {0.667, 0.786, 0.70}, {1015.86, 1015.66, 1015.8}, {}, Marker::circle, false, false, false, 0};
  s.point_labels = {"0.667", "0.786", "0.7"};
  c.series.push_back(s);
  const std::string svg = render_svg(c);
  EXPECT_NE(svg.find(">0.667</text>"), std::string::npos);
  EXPECT_NE(svg.find("text-anchor=\"end\">0.786</text>"), std::string::npos);
  // The third collides on every side near its point: it is moved out with
  // a leader line back to its point, never left out.
  EXPECT_NE(svg.find(">0.7</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<line class=\"leader\""), std::string::npos) << svg;
  EXPECT_EQ(svg.find("had no free place"), std::string::npos) << svg;
}

// U_1 belongs to the finest grid: the subtitle quotes f_1 ± U_1 (U_1 to two
// significant digits), the f0 line and subtitle f0 alone, to the digits U_1
// supports — never f0 ± U_1. Series A: f0 = 1000, finest Δ* = 0.5 with
// f_1 = 1000 + 8·0.5 = 1004, U_1 = 1.25·4 + 0.5 = 5.5.
TEST(ChartRules, F0RoundedToTheDigitsUSupports) {
  EXPECT_EQ(format_with_uncertainty(1016.9954, 1.52), "1017.0 ± 1.5");
  EXPECT_EQ(format_with_uncertainty(1016.9413, 0.2712), "1016.94 ± 0.27");
  EXPECT_EQ(format_to_uncertainty_digits(1016.9413, 0.2712), "1016.94");
  const Chart chart = series_chart(test::synthetic_summaries()[0], 0);
  EXPECT_NE(chart.subtitle.find("f_{0} = 1000.0,"), std::string::npos) << chart.subtitle;
  EXPECT_EQ(chart.subtitle.find("f_{0} = 1000.0 ±"), std::string::npos) << chart.subtitle;
  EXPECT_NE(chart.subtitle.find("f_{1} = 1004.0 ± 5.5 (finest Δ* = 0.5)"), std::string::npos) << chart.subtitle;
  ASSERT_EQ(chart.hlines.size(), 1u);
  EXPECT_EQ(chart.hlines[0].label, "f_{0} = 1000.0");
  EXPECT_NE(chart.subtitle.find("σ_{RE}/R_{f}"), std::string::npos);
}

// Series A has 4 grids (one degree of freedom): σ_RE/R_f = 0.125 < 1 is not
// called a good fit, the subtitle says the fit cannot be judged.
TEST(ChartRules, SubtitleClaimsNoGoodFitWithOneDegreeOfFreedom) {
  const Chart chart = series_chart(test::synthetic_summaries()[0], 0);
  EXPECT_EQ(chart.subtitle.find("good fit"), std::string::npos) << chart.subtitle;
  EXPECT_NE(chart.subtitle.find("(fit cannot be judged: 1 degree(s) of freedom)"), std::string::npos)
      << chart.subtitle;
}

// With a mixed fit chosen the subtitle's p is the rejected power law's and
// says so; with the power law chosen it is the fit's own order.
TEST(ChartRules, SubtitleSaysWhosePIsShown) {
  auto s = test::synthetic_summaries()[0];
  ASSERT_TRUE(s.extrapolation.has_value());
  s.extrapolation->p = 2.13;
  s.extrapolation->method = "power";
  const std::string power = series_chart(s, 0).subtitle;
  EXPECT_NE(power.find(", p = 2.13"), std::string::npos) << power;
  EXPECT_EQ(power.find("rejected"), std::string::npos) << power;
  s.extrapolation->method = "mixed";
  const std::string mixed = series_chart(s, 0).subtitle;
  EXPECT_NE(mixed.find("power law's p = 2.13 (rejected)"), std::string::npos) << mixed;
}

// Series A has two triplets, both monotone with GCI_fine = 0.001, at
// h1 = 0.5 and 1 (f = 1004, 1008): bands ±1.004 and ±1.008 at 1.02·h1.
TEST(ChartRules, GciBandsByConvergenceType) {
  const Chart chart = gci_chart(test::synthetic_summaries()[0], 0);
  const ChartSeries* band = nullptr;
  for (const auto& s : chart.series) {
    if (s.name.find("monotone") != std::string::npos) band = &s;
    EXPECT_EQ(s.name.find("oscillatory"), std::string::npos);  // no empty legend entries
  }
  ASSERT_NE(band, nullptr);
  ASSERT_EQ(band->x.size(), 2u);
  EXPECT_DOUBLE_EQ(band->x[0], 0.51);
  EXPECT_DOUBLE_EQ(band->x[1], 1.02);
  EXPECT_DOUBLE_EQ(band->y[0], 1004.0);
  EXPECT_NEAR(band->y_error[0], 1.004, 1e-12);
  EXPECT_NEAR(band->y_error[1], 1.008, 1e-12);
  EXPECT_NE(render_svg(chart).find("GCI band, monotone triplet"), std::string::npos);
}

// Hand-made points (RDE, cost): B(2, 5) dominates C(2.5, 6); A(1, 10)
// dominates E(1, 12); D(0.5, 20) is the most accurate; G equals B (kept);
// F has no RDE. Front by RDE: D, A, B, G.
TEST(ChartRules, ParetoFrontExcludesDominatedPoints) {
  const std::vector<CostPoint> pts{{1, 10}, {2, 5}, {2.5, 6}, {0.5, 20}, {1, 12}, {NAN, 1}, {2, 5}};
  EXPECT_EQ(pareto_front(pts), (std::vector<std::size_t>{3, 0, 1, 6}));
  EXPECT_TRUE(pareto_front({}).empty());
  // A cheaper and more accurate point dominates everything else.
  EXPECT_EQ(pareto_front({{3, 3}, {1, 1}, {2, 2}}), (std::vector<std::size_t>{1}));
}

// In the synthetic data a finer grid is always more accurate and dearer, so
// every grid of A (converged) is on its front. B is pre-asymptotic: its 4
// grids are drawn hollow and dashed, never as a front, and every legend
// carries the series' verdict.
TEST(ChartRules, SpeedAccuracyChartsPlotTheFront) {
  for (auto measure : {CostMeasure::cpu_seconds, CostMeasure::cell_iterations}) {
    const Chart chart = speed_accuracy_chart(test::synthetic_summaries(), measure);
    ASSERT_EQ(chart.series.size(), 3u);
    EXPECT_EQ(chart.series[0].x.size(), 4u);
    EXPECT_EQ(chart.series[0].point_labels[0], "Δ* 0.5");  // most accurate first
    EXPECT_EQ(chart.series[0].name, "PC1 superbee fwhm6 bvk (converged)");
    EXPECT_FALSE(chart.series[0].hollow);
    const ChartSeries& b = chart.series[1];
    EXPECT_EQ(b.name, "PC1 superbee fwhm6 hkl (pre-asymptotic)");
    EXPECT_EQ(b.x.size(), 4u);
    EXPECT_TRUE(b.hollow);
    EXPECT_TRUE(b.dashed);
    EXPECT_TRUE(b.point_labels.empty());                  // no front labels
    EXPECT_TRUE(chart.series.back().faded);               // the "dominated" legend entry
  }
  // Cost of A's finest grid: 60×400×20 cells × (100 + 200) iterations.
  const GridPoint g = test::grid(0.5, test::kA);
  EXPECT_DOUBLE_EQ(grid_cost(g, CostMeasure::cell_iterations), 60.0 * 400 * 20 * 300);
  EXPECT_DOUBLE_EQ(grid_cost(g, CostMeasure::cpu_seconds), 2 * 10 / 0.125);
}

// The cheapest grid for each target recomputed by brute force from the
// manufactured data: RDE_i = (Fs|f0 − f_i| + σ)/f0, least CPU time among
// the grids that meet the target with every finer grid.
TEST(ChartRules, TargetTableMatchesABruteForceSearch) {
  const auto s = test::synthetic_summaries();
  const std::vector<double> targets{0.05, 0.02, 0.01, 0.005};
  const Table t = cost_table(s, targets);
  std::size_t row = 0;
  for (const auto* m : {&test::kA, &test::kB}) {
    for (double target : targets) {
      ASSERT_LT(row, t.rows.size());
      double best_h = -1, best_cpu = INFINITY;
      for (double h : {0.5, 1.0, 1.5, 2.0}) {
        const GridPoint g = test::grid(h, *m);
        auto rde = [&](double x) { return (test::kFs * std::abs(m->f0 - m->f(x)) + test::kSigma) / m->f0; };
        bool finer_meet = true;
        for (double finer : {0.5, 1.0, 1.5, 2.0}) finer_meet = finer_meet && (finer > h || rde(finer) <= target);
        if (finer_meet && g.cpu_s < best_cpu) {
          best_cpu = g.cpu_s;
          best_h = h;
        }
      }
      const auto& r = t.rows[row++];
      if (m == &test::kB) {  // B is pre-asymptotic: no grid is named, the table says why
        EXPECT_EQ(r[3].exact, "— (series pre-asymptotic)") << "target " << target;
        EXPECT_EQ(r[6].exact, "");
        continue;
      }
      if (best_h < 0) {
        EXPECT_EQ(r[3].exact, "none of the run grids") << "target " << target;
        continue;
      }
      EXPECT_DOUBLE_EQ(std::stod(r[3].exact), best_h) << "target " << target;
      EXPECT_DOUBLE_EQ(std::stod(r[6].exact), best_cpu);
      EXPECT_DOUBLE_EQ(std::stod(r[7].exact), test::grid(best_h, *m).peak_rss_mb);
    }
  }
  EXPECT_EQ(row, t.rows.size());
  EXPECT_EQ(t.columns[7].name, "peak_rss_mb");
}

// Without any converged series nothing can be recommended: the
// speed-accuracy charts have no series and report_charts() leaves them out;
// the RDE chart still shows every series, its legend naming the verdict.
TEST(ChartRules, NoSpeedAccuracyChartWithoutAConvergedSeries) {
  auto s = test::synthetic_summaries();
  s[0].verdict = "unreliable";
  EXPECT_TRUE(speed_accuracy_chart(s, CostMeasure::cpu_seconds).series.empty());
  for (const NamedChart& c : report_charts(s)) {
    EXPECT_NE(c.file, "speed_accuracy.svg");
    EXPECT_NE(c.file, "speed_accuracy_work.svg");
  }
  const Chart rde = rde_chart(s);
  ASSERT_EQ(rde.series.size(), 2u);
  EXPECT_EQ(rde.series[0].name, "PC1 superbee fwhm6 bvk (unreliable)");
  EXPECT_TRUE(rde.series[0].dashed);
  EXPECT_TRUE(rde.series[0].hollow);
  const auto all = report_charts(test::synthetic_summaries());
  EXPECT_EQ(std::count_if(all.begin(), all.end(), [](const NamedChart& c) {
              return c.file.rfind("speed_accuracy", 0) == 0;
            }), 2);
}

// The study's target RDE (adaptive grids) is drawn on the RDE chart as a
// dashed black line at the target, in percent; without a target, no line.
TEST(ChartRules, TheRdeChartDrawsTheStudysTarget) {
  const auto s = test::synthetic_summaries();
  EXPECT_TRUE(rde_chart(s).hlines.empty());
  const Chart with = rde_chart(s, 0.002);
  ASSERT_EQ(with.hlines.size(), 1u);
  EXPECT_DOUBLE_EQ(with.hlines[0].y, 0.2);
  EXPECT_NE(with.hlines[0].label.find("target RDE 0.2"), std::string::npos) << with.hlines[0].label;
  EXPECT_TRUE(with.hlines[0].dashed);
}

}  // namespace
}  // namespace gridfree
