// SPDX-License-Identifier: GPL-3.0-or-later
// The stability map (report/stability_map.h, stability_section.h): every
// outcome word from a grid's status and reason, the per-series line, the
// GCI-vs-least-squares tally, failures first and the row cap, and the SVG's
// hover reasons.
#include <gtest/gtest.h>

#include <string>

#include "report/report_content.h"
#include "report/stability_map.h"
#include "report/stability_section.h"
#include "report_test_data.h"
#include "xml_check.h"

namespace gridfree {
namespace {

TEST(StabilityOutcome, EveryStatusAndReasonHasItsWord) {
  EXPECT_EQ(grid_outcome("converged", "", "converged"), "converged");
  EXPECT_EQ(grid_outcome("not_converged", "not converged after 200 iterations", "stalled"), "stalled");
  EXPECT_EQ(grid_outcome("not_converged", "not converged after stalling for 200 iterations at iteration 229", ""),
            "stalled");  // a result from before the outcome field
  EXPECT_EQ(grid_outcome("not_converged", "not converged after 20000 iterations: ...", ""), "iteration_cap");
  EXPECT_EQ(grid_outcome("not_converged", "anything", "iteration_cap"), "iteration_cap");
  EXPECT_EQ(grid_outcome("diverged", "diverged at iteration 12", "diverged"), "diverged");
  EXPECT_EQ(grid_outcome("invalid", "centroid deposition puts solids fraction eps_s = 2.09", "invalid"), "invalid");
  EXPECT_EQ(grid_outcome("failed", "timed out: after 600 s (after 2 attempts)", ""), "timed_out");
  EXPECT_EQ(grid_outcome("failed", "worker exit 1 [log: ... timed out ...]", ""), "failed");
  EXPECT_EQ(grid_outcome("queued", "", ""), "pending");
  EXPECT_EQ(grid_outcome("running", "", ""), "pending");
  EXPECT_EQ(grid_outcome("cancelled", "", ""), "cancelled");
  for (const char* f : {"stalled", "iteration_cap", "diverged", "invalid", "timed_out", "failed"})
    EXPECT_TRUE(is_failure_outcome(f)) << f;
  for (const char* ok : {"converged", "pending", "cancelled"}) EXPECT_FALSE(is_failure_outcome(ok)) << ok;
}

// A series on five grids, coarsest converged, then one outcome per finer grid.
SeriesSummary stability_series_with(const std::vector<std::pair<double, std::string>>& grids) {
  SeriesSummary s;
  s.label = "bed superbee fwhm6 bvk centroid";
  for (const auto& [h, status] : grids) {
    GridPoint g = test::grid(h, test::kA, status == "stalled" ? "not_converged" : status);
    if (status == "stalled") g.worker_outcome = "stalled";
    if (status != "converged") g.reason = status + " at " + std::to_string(h);
    s.series.grids.push_back(g);
  }
  return s;
}

TEST(StabilityLine, ConvergesDownToTheLastGridBeforeTheFirstFailure) {
  const auto s = stability_series_with({{1.0, "invalid"}, {3.3, "converged"}, {2.0, "converged"}, {0.7, "invalid"}});
  EXPECT_EQ(stability_line(s),
            "solved down to Δ* 2; first failure at Δ* 1: invalid (invalid at 1.000000); 2 failed grids in all");
  const auto all = stability_series_with({{3.3, "converged"}, {2.0, "converged"}});
  EXPECT_EQ(stability_line(all), "solved on every finished grid, down to Δ* 2");
  const auto coarse = stability_series_with({{3.3, "stalled"}, {2.0, "converged"}, {1.0, "queued"}});
  EXPECT_EQ(stability_line(coarse),
            "fails from the coarsest grid: first failure at Δ* 3.3: stalled (stalled at 3.300000); 1 finer grid(s) "
            "solved again (1 grid(s) not finished)");
}

TEST(StabilityMethods, GciTripletsAreCountedUsableOnlyWhenMonotoneWithPInRange) {
  SeriesSummary s = stability_series_with({{2.0, "converged"}});
  ExtrapolationView v;
  v.status = "ok";
  v.method = "capped_power";
  v.f0 = 1000;
  auto triplet = [](std::optional<double> p, std::string convergence) {
    GciView g;
    g.p = p;
    g.f_ext = 1000;
    g.convergence = std::move(convergence);
    g.status = "ok";
    return g;
  };
  v.gci = {triplet(1.0, "monotone"), triplet(-0.4, "monotone"), triplet(5.0, "monotone"),
           triplet(1.2, "oscillatory"), triplet(std::nullopt, "divergent")};
  s.extrapolation = v;
  const MethodTally t = method_tally(s, 0.5, 2.1);
  EXPECT_EQ(t.triplets, 5);
  EXPECT_EQ(t.gci_usable, 1);
  EXPECT_EQ(t.p_out_of_range, 2);
  EXPECT_EQ(t.oscillatory, 1);
  EXPECT_EQ(t.divergent, 1);
  EXPECT_TRUE(t.least_squares_usable);
  EXPECT_EQ(t.least_squares, "f0 by capped_power");
  s.extrapolation.reset();
  s.extrapolation_error = "no converged grid";
  EXPECT_FALSE(method_tally(s, 0.5, 2.1).least_squares_usable);
}

// The GCI table's `usable` column and the tally apply one rule: a status-ok
// triplet with p = 4.22 is "p outside the range" in both.
TEST(StabilityMethods, GciTableAndTallyAgreeOnEveryTriplet) {
  SeriesSummary s = stability_series_with({{2.0, "converged"}});
  ExtrapolationView v;
  v.status = "ok";
  v.f0 = 1000;
  for (const auto& [p, conv] : std::vector<std::pair<std::optional<double>, std::string>>{
           {4.22, "monotone"}, {1.0, "monotone"}, {1.0, "divergent"}, {std::nullopt, "monotone"}}) {
    GciView g;
    g.p = p;
    g.f_ext = 1000;
    g.convergence = conv;
    g.status = "ok";
    v.gci.push_back(g);
  }
  s.extrapolation = v;
  EXPECT_EQ(gci_usability(v.gci[0], 0.5, 2.1), "p outside [0.5, 2.1]");
  EXPECT_EQ(gci_usability(v.gci[1], 0.5, 2.1), "usable");
  EXPECT_EQ(gci_usability(v.gci[2], 0.5, 2.1), "divergent");
  EXPECT_EQ(gci_usability(v.gci[3], 0.5, 2.1), "no p");
  const MethodTally t = method_tally(s, 0.5, 2.1);
  EXPECT_EQ(t.p_out_of_range, 1);
  EXPECT_EQ(t.gci_usable, 1);
  EXPECT_EQ(t.divergent, 1);
  EXPECT_EQ(t.no_number, 1);
}

TEST(StabilityMap, FailuresFirstOneColumnPerDeltaStarAndTheCapSaysWhatItOmits) {
  std::vector<SeriesSummary> all;
  for (int i = 0; i < 5; ++i) {
    auto s = stability_series_with({{3.3, "converged"}, {2.0, "converged"}});
    s.label = "ok" + std::to_string(i);
    all.push_back(s);
  }
  auto bad = stability_series_with({{3.3, "converged"}, {2.0, "invalid"}, {1.0, "invalid"}});
  bad.label = "bad";
  all.push_back(bad);
  const StabilityMap m = stability_map(all, 0.5, 2.1, 3);
  ASSERT_EQ(m.columns, (std::vector<double>{3.3, 2.0, 1.0}));
  ASSERT_EQ(m.rows.size(), 3u);
  EXPECT_EQ(m.rows[0].label, "bad");
  EXPECT_EQ(m.rows[0].failures, 2);
  EXPECT_EQ(m.rows[0].cells[1].outcome, "invalid");
  EXPECT_EQ(m.rows[1].label, "ok0");
  EXPECT_FALSE(m.rows[1].cells[2].present);
  EXPECT_EQ(m.omitted, 3);
  EXPECT_EQ(m.series_total, 6);
  EXPECT_EQ(m.series_with_failures, 1);

  const std::string svg = stability_svg(m);
  EXPECT_EQ(test::xml_problem(svg), "");
  EXPECT_NE(svg.find("<title>bad, Δ* 2: invalid: invalid at 2.000000</title>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("outcome-converged"), std::string::npos);
  const Table wide = stability_wide_table(m);
  ASSERT_EQ(wide.columns.size(), 4u);
  EXPECT_EQ(wide.rows[0][2].shown, "invalid");
  EXPECT_EQ(wide.rows[1][1].shown.rfind("✓ ", 0), 0u);
}

// A grid on which numerics.stall_remedy acted (the result's
// extra.correction_relaxed_from_iteration) is marked "R" in the map and its
// wide table, says from which iteration on hover and in the grid table, and
// the legend explains the mark; a map without such a grid has no legend line.
TEST(StabilityMap, AGridTheStallRemedyActedOnIsMarkedWithTheIteration) {
  auto s = stability_series_with({{3.3, "converged"}, {2.0, "converged"}, {1.0, "stalled"}});
  s.series.grids[0].iterations = 81;
  s.series.grids[1].iterations = 325;
  s.series.grids[1].remedy_from_iteration = 239;
  s.series.grids[2].remedy_from_iteration = 266;
  const StabilityMap m = stability_map({s}, 0.5, 2.1);
  const std::string svg = stability_svg(m);
  EXPECT_EQ(test::xml_problem(svg), "");
  EXPECT_NE(svg.find(">✓ 325 R</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">✓ 81</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">stalled R</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("solved in 325 outer iterations; numerics.stall_remedy relaxed the deferred correction from "
                     "outer iteration 239"),
            std::string::npos)
      << svg;
  EXPECT_NE(svg.find("R: numerics.stall_remedy acted"), std::string::npos);
  const Table wide = stability_wide_table(m);
  EXPECT_EQ(wide.rows[0][2].shown, "✓ 325 R");
  const Table grids = stability_grid_table({s});
  ASSERT_EQ(grids.rows.size(), 3u);
  EXPECT_EQ(grids.rows[1][5].exact, "numerics.stall_remedy relaxed the deferred correction from outer iteration 239 "
                                    "(after a first stall)");
  EXPECT_EQ(grids.rows[0][5].exact, "");

  const auto plain = stability_series_with({{3.3, "converged"}, {2.0, "stalled"}});
  EXPECT_EQ(stability_svg(stability_map({plain}, 0.5, 2.1)).find("R: numerics.stall_remedy"), std::string::npos);
}

TEST(StabilitySection, EveryReportHasTheMapItsCsvAndTheWordStability) {
  const ReportContent c = build_report_content(test::synthetic_study(), test::fake_extrapolation);
  const std::string html = stability_section_html(c);
  EXPECT_NE(html.find("id=\"stability\""), std::string::npos);
  EXPECT_NE(html.find("Stability:"), std::string::npos);
  EXPECT_NE(html.find("diverged at iteration 12"), std::string::npos);  // series B's reason, on hover
  EXPECT_NE(html.find("first failure at Δ* 0.25: diverged"), std::string::npos) << html;
  EXPECT_NE(render_html(c).find("Where methods fail"), std::string::npos);
  EXPECT_NE(render_markdown(c).find("## Where methods fail (stability map)"), std::string::npos);
  const Table grids = stability_grid_table(c.series);
  int invalid_or_diverged = 0;
  for (const auto& row : grids.rows) invalid_or_diverged += row[3].exact == "diverged";
  EXPECT_EQ(invalid_or_diverged, 1);
}

}  // namespace
}  // namespace gridfree
