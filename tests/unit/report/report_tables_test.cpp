// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the series digest, one-factor differences and table renderings,
// on the synthetic study of report_test_data.h (expected values computed
// here from the manufactured data, not read back from the report code).
#include <cmath>

#include <gtest/gtest.h>

#include "report/cost_table.h"
#include "report/differences.h"
#include "report/report_charts.h"
#include "report/svg_chart.h"
#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/report_tables.h"
#include "report/series_summary.h"
#include "report_test_data.h"

namespace gridfree {
namespace {

TEST(ReportSeries, LabelNamesTheFactors) {
  SeriesData s{0, "PC1", "superbee", "bvk", "diffusion", 6, "done", {}, {}};
  EXPECT_EQ(s.label(), "PC1 superbee fwhm6 bvk");
  s.fwhm_dp = 4.5;
  EXPECT_EQ(s.label(), "PC1 superbee fwhm4.5 bvk");
  s.deposition = "centroid";
  EXPECT_EQ(s.label(), "PC1 superbee centroid bvk");
}

TEST(ReportSeries, SummaryCountsAndSortsGrids) {
  const auto s = test::synthetic_summaries();
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].h, (std::vector<double>{0.5, 1.0, 1.5, 2.0}));
  EXPECT_EQ(s[0].f[0], 1004.0);  // 1000 + 8·0.5
  EXPECT_FALSE(s[0].insufficient());
  EXPECT_FALSE(s[0].incomplete);
  EXPECT_EQ(s[1].converged(), 4);
  EXPECT_EQ(s[1].failed, 1);
  EXPECT_EQ(s[1].series.grids.front().status, "diverged");  // Δ* 0.25 sorts first
  EXPECT_EQ(s[2].converged(), 3);
  EXPECT_EQ(s[2].pending, 1);
  EXPECT_TRUE(s[2].insufficient());
  EXPECT_TRUE(s[2].incomplete);
  EXPECT_NE(s[2].note().find("insufficient grids (3 solved, 4 needed)"), std::string::npos);
  EXPECT_NE(s[2].note().find("incomplete (1 of 4 grids pending)"), std::string::npos);
  EXPECT_FALSE(s[2].f0().has_value());
  // |f − f0|/f0 of A's coarsest grid: 16/1000.
  EXPECT_DOUBLE_EQ(*s[0].relative_error(1016.0), 0.016);
}

TEST(ReportSeries, ExtrapolatorFailureIsRecordedNotThrown) {
  const auto s = summarize_series(test::synthetic_study(),
                                  [](const std::vector<double>&, const std::vector<double>&) -> nlohmann::json {
                                    throw std::runtime_error("boom");
                                  });
  EXPECT_FALSE(s[0].extrapolation.has_value());
  EXPECT_EQ(s[0].extrapolation_error, "boom");
  EXPECT_NE(s[0].note().find("extrapolation: boom"), std::string::npos);
}

TEST(ReportDifferences, RelativeDifferenceFormula) {
  // 2|1000 − 1500|/(1000 + 1500) = 0.4.
  EXPECT_DOUBLE_EQ(*relative_difference(1000, 1500), 0.4);
  EXPECT_DOUBLE_EQ(*relative_difference(1500, 1000), 0.4);
  EXPECT_DOUBLE_EQ(*relative_difference(-10, -12), 2.0 * 2 / 22);
  EXPECT_FALSE(relative_difference(1, -1).has_value());
  EXPECT_FALSE(relative_difference(NAN, 1).has_value());
}

TEST(ReportDifferences, OnlyPairsDifferingInExactlyOneFactor) {
  const auto s = test::synthetic_summaries();
  const auto d = one_factor_differences(s);
  ASSERT_EQ(d.size(), 2u);  // A–B (drag), A–C (case); B–C differ in two
  EXPECT_EQ(d[0].factor, "drag");
  EXPECT_EQ(d[0].value_a, "bvk");
  EXPECT_EQ(d[0].value_b, "hkl");
  EXPECT_DOUBLE_EQ(*d[0].relative, 2.0 * 500 / 2500);
  EXPECT_EQ(d[1].factor, "case");
  EXPECT_FALSE(d[1].relative.has_value());  // C has no f0 (3 grids)
}

TEST(ReportDifferences, FilterWidthAndDepositionAreFactors) {
  std::vector<SeriesSummary> s(3);
  s[0].series = {0, "PC1", "superbee", "bvk", "diffusion", 4, "done", {}, {}};
  s[1].series = {0, "PC1", "superbee", "bvk", "diffusion", 8, "done", {}, {}};
  s[2].series = {0, "PC1", "superbee", "bvk", "centroid", 4, "done", {}, {}};
  const auto d = one_factor_differences(s);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].factor, "fwhm_dp");
  EXPECT_EQ(d[0].value_b, "8");
  EXPECT_EQ(d[1].factor, "deposition");
}

// U of each series' finest grid from the manufactured data: A (h = 0.5):
// f = 1004, U = 1.25·4 + 0.5 = 5.5; B (h = 0.5, its 0.25 diverged): f = 1502.5,
// U = 1.25·2.5 + 0.5 = 3.625. |1000 − 1500| = 500 > √(5.5² + 3.625²) = 6.587.
TEST(ReportDifferences, DifferenceAgainstCombinedUncertaintyAndVerdicts) {
  const auto s = test::synthetic_summaries();
  const auto d = one_factor_differences(s);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_DOUBLE_EQ(*d[0].u_a, 5.5);
  EXPECT_DOUBLE_EQ(*d[0].u_b, 3.625);
  EXPECT_NEAR(*d[0].u_combined, std::sqrt(5.5 * 5.5 + 3.625 * 3.625), 1e-12);
  EXPECT_NEAR(*d[0].u_relative, 2 * *d[0].u_combined / 2500, 1e-15);
  EXPECT_TRUE(*d[0].exceeds_u);
  // The fake extrapolator gives no verdict: not converged, so the pair is marked.
  EXPECT_FALSE(d[0].both_converged());
  const Table t = differences_table(s, d);
  EXPECT_EQ(t.rows[0].back().exact.rfind("⚠", 0), 0u);
  EXPECT_FALSE(d[1].exceeds_u.has_value());  // C has no f0
  EXPECT_EQ(d[1].verdict_b, "insufficient_grids");
}

TEST(ReportTables, PowerLawPAndCShownOnlyWhenThePowerLawIsChosen) {
  const Table t = series_table(test::synthetic_summaries(), 0.5, 2.1);
  std::size_t p = 0, c = 0, method = 0;
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    if (t.columns[i].name == "p") p = i;
    if (t.columns[i].name == "c") c = i;
    if (t.columns[i].name == "method") method = i;
  }
  EXPECT_EQ(t.rows[0][method].exact, "power");
  EXPECT_EQ(t.rows[0][p].exact, "1");
  EXPECT_EQ(t.rows[0][c].exact, "8");
  EXPECT_EQ(t.rows[1][method].exact, "mixed");  // B: the fake chooses mixed for p = 2
  EXPECT_EQ(t.rows[1][p].exact, "");
  EXPECT_EQ(t.rows[1][c].exact, "");
}

// Series A (f = 1000 + 8h, U = 1.25·8h + 0.5): RDE = (10h + 0.5)/1000 =
// 0.55, 1.05, 1.55, 2.05 % on h = 0.5, 1, 1.5, 2; CPU = 20/h³ s.
TEST(ReportTables, CheapestGridForATargetRde) {
  const auto s = test::synthetic_summaries();
  auto h_for = [&](double target) {
    const GridPoint* g = cheapest_grid_for(s[0], target);
    return g ? g->delta_star : -1.0;
  };
  EXPECT_EQ(h_for(0.10), 2.0);
  EXPECT_EQ(h_for(0.0205), 2.0);  // meets the target exactly
  EXPECT_EQ(h_for(0.02), 1.5);
  EXPECT_EQ(h_for(0.01), 0.5);
  EXPECT_EQ(h_for(0.005), -1.0);
  const Table t = cost_table(s, {0.02, 0.005});
  ASSERT_EQ(t.rows.size(), 4u);  // A and B; C has no extrapolation with U
  EXPECT_EQ(t.rows[0][3].exact, "1.5");
  EXPECT_DOUBLE_EQ(std::stod(t.rows[0][6].exact), 20 / (1.5 * 1.5 * 1.5));
  EXPECT_EQ(t.rows[1][3].exact, "none of the run grids");
}

// Oscillatory data: A with f(1) moved from 1008 to 1016 has RDE (1.25|f0 −
// f| + 0.5)/1000 = 0.55, 2.05, 1.55, 2.05 % on h = 0.5, 1, 1.5, 2. Δ* 1.5
// meets 2 % on its own but Δ* 1 below it does not, so the cheapest grid that
// keeps 2 % on refinement is 0.5; for 2.1 % every grid keeps it and the
// cheapest (2) is named.
TEST(ReportTables, CheapestGridMustKeepTheTargetOnEveryFinerGrid) {
  StudyReportData d = test::synthetic_study();
  for (GridPoint& g : d.series[0].grids)
    if (g.delta_star == 1.0) g.dp_star = 1016.0;
  const auto s = summarize_series(d, test::fake_extrapolation);
  auto h_for = [&](double target) {
    const GridPoint* g = cheapest_grid_for(s[0], target);
    return g ? g->delta_star : -1.0;
  };
  ASSERT_TRUE(s[0].extrapolation);
  ASSERT_NEAR(*s[0].extrapolation->grid_at(1.0)->rde, 0.0205, 1e-12);
  ASSERT_NEAR(*s[0].extrapolation->grid_at(1.5)->rde, 0.0155, 1e-12);
  EXPECT_EQ(h_for(0.02), 0.5);
  EXPECT_EQ(h_for(0.021), 2.0);
  EXPECT_EQ(h_for(0.0205), 2.0);  // meets the target exactly on 1 and 2
  EXPECT_EQ(h_for(0.005), -1.0);
}

// B's chosen fit is the mixed one: its power law is drawn faded and
// labelled "rejected", the mixed fit labelled "chosen" at full opacity.
TEST(ReportCharts, RejectedFitIsFadedAndLabelled) {
  const auto s = test::synthetic_summaries();
  const Chart chart = series_chart(s[1], 1);
  int rejected = 0, chosen = 0;
  for (const auto& c : chart.series) {
    if (c.name.find("(rejected)") != std::string::npos) {
      ++rejected;
      EXPECT_TRUE(c.faded);
      EXPECT_NE(c.name.find("power law"), std::string::npos);
    }
    if (c.name.find("(chosen)") != std::string::npos) {
      ++chosen;
      EXPECT_FALSE(c.faded);
      EXPECT_NE(c.name.find("mixed"), std::string::npos);
    }
  }
  EXPECT_EQ(rejected, 1);
  EXPECT_EQ(chosen, 1);
  const std::string svg = render_svg(chart);
  EXPECT_NE(svg.find("stroke-opacity=\"0.35\""), std::string::npos);
  // Each converged point carries its Δ* (B: 0.5, 1, 1.5, 2).
  for (const char* label : {">0.5</text>", ">1</text>", ">1.5</text>", ">2</text>"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(ReportTables, SeriesTableHasFitQualityAndNotes) {
  const Table t = series_table(test::synthetic_summaries(), 0.5, 2.1);
  ASSERT_EQ(t.rows.size(), 3u);
  auto col = [&](const std::string& name) {
    for (std::size_t i = 0; i < t.columns.size(); ++i) {
      if (t.columns[i].name == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return std::size_t{0};
  };
  EXPECT_EQ(t.rows[0][col("f0")].exact, "1000");
  EXPECT_EQ(t.rows[0][col("method")].exact, "power");
  // A: R_f = (1016 − 1004)/3 = 4, σ_RE/R_f = 0.5/4 = 0.125.
  EXPECT_DOUBLE_EQ(std::stod(t.rows[0][col("data_range")].exact), 4.0);
  EXPECT_DOUBLE_EQ(std::stod(t.rows[0][col("sigma_re_over_rf")].exact), 0.125);
  // A has 4 grids: one degree of freedom, the fit cannot be judged (no "yes").
  EXPECT_EQ(t.rows[0][col("good_fit")].exact, "cannot be judged");
  EXPECT_EQ(t.rows[1][col("failed")].exact, "1");
  EXPECT_EQ(t.rows[2][col("f0")].exact, "");
  EXPECT_NE(t.rows[2][col("note")].exact.find("insufficient grids"), std::string::npos);
  EXPECT_EQ(t.rows[2][col("status")].exact, "running");
}

TEST(ReportTables, CsvQuotesAndMarkdownEscapes) {
  Table t;
  t.columns = {{"a", "A", false, false}, {"b", "B", true, true}, {"c", "C|x", false, true}};
  t.rows.push_back({text_cell("x, \"y\""), number_cell(0.1), number_cell(1158.812345678, 5)});
  EXPECT_EQ(to_csv(t), "a,b,c\n\"x, \"\"y\"\"\",0.1,1158.812345678\n");
  EXPECT_EQ(to_markdown(t), "| A | C\\|x |\n| --- | ---: |\n| x, \"y\" | 1158.8 |\n");
  const std::string html = to_html(t);
  EXPECT_NE(html.find("<td>x, &quot;y&quot;</td><td class=\"num\">1158.8</td>"), std::string::npos);
  EXPECT_EQ(html.find("0.1"), std::string::npos);  // csv-only column left out
}

TEST(ReportTables, FailuresListEveryUnusableGridWithItsReason) {
  const Table t = failures_table(test::synthetic_summaries());
  ASSERT_EQ(t.rows.size(), 1u);  // the diverged grid; the queued one is pending, not failed
  EXPECT_EQ(t.rows[0][0].exact, "PC1 superbee fwhm6 hkl");
  EXPECT_EQ(t.rows[0][3].exact, "diverged");
  EXPECT_EQ(t.rows[0][5].exact, "residual grew by 1e6, diverged at iteration 12");
}

TEST(ReportTables, GciTableComparesWithF0) {
  const Table t = gci_table(test::synthetic_summaries(), 0.5, 2.1);
  // A and B: 4 grids → 2 triplets each; C: 3 grids → 1 triplet.
  ASSERT_EQ(t.rows.size(), 5u);
  // A's second triplet: φ_ext = 1000 + 100 → (φ_ext − f0)/f0 = 0.1.
  EXPECT_DOUBLE_EQ(std::stod(t.rows[1][11].exact), 0.1);
  EXPECT_EQ(t.rows[4][11].exact, "");  // C has no f0
  // The usable column applies the stability section's rule to each row.
  ASSERT_EQ(t.columns[9].name, "usable");
  for (const auto& row : t.rows) {
    const std::string& use = row[9].exact;
    EXPECT_TRUE(use == "usable" || use == "divergent" || use == "oscillatory" || use == "no p" ||
                use.rfind("p outside [0.5, 2.1]", 0) == 0)
        << use;
  }
}

// The verdict line prints f0 without ± and the finest grid as f₁ ± U₁: U₁ is
// an interval about f₁, not about f0. Series A: f0 = 1000, f₁ = 1004 at
// Δ* = 0.5, U₁ = 1.25·4 + 0.5 = 5.5.
TEST(ReportTables, VerdictHeadlineGivesUOnlyWithTheFinestGrid) {
  ReportContent c;
  c.series = test::synthetic_summaries();
  const auto items = verdict_items(c);
  ASSERT_EQ(items.size(), 3u);
  const std::string& h = items[0].headline;
  EXPECT_EQ(h.rfind("f0 = 1000.0; ", 0), 0u) << h;
  EXPECT_NE(h.find("finest grid Δ* = 0.5: f₁ = 1004.0 ± 5.5 (U₁, RDE"), std::string::npos) << h;
  EXPECT_EQ(h.find("f0 = 1000.0 ±"), std::string::npos) << h;
  EXPECT_EQ(items[2].headline, "no extrapolated value");
}

// No column mixes notations: one cell in exponent form puts the column's
// other plain numbers in it (their digits kept); other columns and cells
// with more than a number stay as they are.
TEST(ReportTables, ANumericColumnHasOneNotation) {
  Table t;
  t.columns = {Column{"c", "", false, true}, Column{"d", "", false, true}, Column{"e", "", false, true}};
  t.rows = {{number_cell(1.2e-5, 3), number_cell(0.5, 3), text_cell("1017.0 ± 1.5")},
            {number_cell(0.000109, 3), number_cell(12.25, 4), text_cell("1.5e-06")},
            {number_cell(8, 3), text_cell(""), text_cell("n/a")}};
  const std::string md = to_markdown(t);
  EXPECT_NE(md.find("| 1.2e-05 | 0.5 | 1017.0 ± 1.5 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1.09e-04 | 12.25 | 1.5e-06 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 8e+00 |  | n/a |"), std::string::npos) << md;
  EXPECT_NE(to_html(t).find("<td class=\"num\">1.09e-04</td>"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
