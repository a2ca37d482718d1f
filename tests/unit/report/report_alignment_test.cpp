// SPDX-License-Identifier: GPL-3.0-or-later
// The report's alignment section (orchestrator/src/report/report_alignment.h):
// the spread rule, the comparison with the grid's U/|f|, the warning, and a
// report without the check showing no section.
#include <gtest/gtest.h>

#include <cmath>

#include "report/report_alignment.h"
#include "report/report_content.h"

namespace gridfree {
namespace {

SeriesSummary summary_with_u(long long id, double h, double f, double u) {
  SeriesSummary s;
  s.series.id = id;
  s.label = "PC1 superbee fwhm6 bvk";
  ExtrapolationView e;
  e.grids.push_back({h, f, f, u, std::nullopt});
  s.extrapolation = e;
  return s;
}

TEST(ReportAlignment, SpreadIsRangeOverMean) {
  EXPECT_NEAR(*alignment_spread({1000.0, 1010.0, 990.0}), 20.0 / 1000.0, 1e-15);
  EXPECT_NEAR(*alignment_spread({1025.5, 1000.8}), (1025.5 - 1000.8) / ((1025.5 + 1000.8) / 2), 1e-15);
  EXPECT_FALSE(alignment_spread({1000.0}).has_value());                // one alignment: no spread
  EXPECT_FALSE(alignment_spread({1000.0, std::nullopt}).has_value());  // a variant not converged
  EXPECT_FALSE(alignment_spread({1000.0, NAN}).has_value());
}

TEST(ReportAlignment, SpreadAboveTheGridsUIsWarned) {
  const std::vector<SeriesSummary> series{summary_with_u(7, 2.0, 1000.0, 5.0)};
  // Spread 2 % against U/|f| = 0.5 %.
  const std::vector<AlignmentGrid> wide{{7, 0, 2.0, {15, 100, 5}, {1000.0, 1010.0, 990.0}}};
  const auto lines = alignment_lines(wide, series);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NEAR(*lines[0].u_relative, 0.005, 1e-15);
  EXPECT_TRUE(lines[0].exceeds());
  const auto warnings = alignment_warnings(lines);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("Δ* = 2"), std::string::npos) << warnings[0];
  const Table t = alignment_table(lines);
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0].back().exact, "yes");
  // Spread 0.2 % against 0.5 %: no warning.
  const std::vector<AlignmentGrid> narrow{{7, 0, 2.0, {15, 100, 5}, {1000.0, 1001.0, 999.0}}};
  EXPECT_TRUE(alignment_warnings(alignment_lines(narrow, series)).empty());
  EXPECT_EQ(alignment_table(alignment_lines(narrow, series)).rows[0].back().exact, "no");
  // A grid of another series is not matched to this one.
  EXPECT_TRUE(alignment_lines({{8, 0, 2.0, {15, 100, 5}, {1.0, 2.0}}}, series).empty());
}

TEST(ReportAlignment, ReportsWithoutTheCheckHaveNoSection) {
  StudyReportData data;
  data.study_name = "plain";
  const auto content = build_report_content(data, [](const std::vector<double>&, const std::vector<double>&) {
    return nlohmann::json::object();
  });
  EXPECT_TRUE(content.alignment.empty());
  EXPECT_EQ(render_markdown(content).find("Alignment check"), std::string::npos);
  EXPECT_EQ(render_html(content).find("Alignment check"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
