// SPDX-License-Identifier: GPL-3.0-or-later
// The coverage self-check in the report (report/series_coverage.h): a table
// row per checked series, the summary line, and a warning in the attention
// list when U missed the answer in too many coarser windows. The series is
// manufactured like the failure measured on real coarse grids:
// f = 100 − h² − 0.1 h³ on 8 grids Δ* 0.5 … 3.3 (apparent order above 2.1).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/report_content.h"
#include "report/report_summary.h"
#include "report/series_coverage.h"

namespace gridfree {
namespace {

StudyReportData cubic_study(bool with_pending) {
  StudyReportData d;
  d.study_name = "coverage";
  SeriesData s{1, "PC1", "superbee", "bvk", "diffusion", 6, with_pending ? "running" : "done", {}, {}};
  for (int i = 0; i < 8; ++i) {
    const double h = 0.5 * std::pow(3.3 / 0.5, i / 7.0);
    GridPoint g;
    g.job_hash = "job-" + std::to_string(i);
    g.delta_star = h;
    g.nx = g.ny = g.nz = 10 + i;
    g.status = with_pending && i == 0 ? "queued" : "converged";
    if (g.status == "converged") g.dp_star = 100 - h * h - 0.1 * h * h * h;
    s.grids.push_back(g);
  }
  d.series = {s};
  return d;
}

ReportContent content_with(const std::string& method, bool with_pending = false) {
  ExtrapolatorSettings settings;
  settings.method = method;
  return build_report_content(cubic_study(with_pending), library_extrapolator(settings));
}

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const auto& l : lines)
    if (l.find(text) != std::string::npos) return true;
  return false;
}

TEST(ReportCoverage, ThePapersMethodIsWarnedTheDefaultIsNot) {
  const ReportContent fm = content_with("fm");
  ASSERT_TRUE(fm.series[0].coverage.has_value());
  const CoverageCheck& c = *fm.series[0].coverage;
  EXPECT_EQ(c.windows.size(), 10u);  // 7 coarser grids: windows of 4 … 7
  EXPECT_TRUE(c.below_promise()) << c.summary();
  EXPECT_TRUE(any_contains(series_warnings(fm), "coarser windows")) << c.summary();
  ASSERT_EQ(fm.coverage_table.table.rows.size(), 1u);

  const ReportContent capped = content_with("capped");
  ASSERT_TRUE(capped.series[0].coverage.has_value());
  EXPECT_FALSE(capped.series[0].coverage->below_promise()) << capped.series[0].coverage->summary();
  EXPECT_FALSE(any_contains(series_warnings(capped), "coarser windows"));
  EXPECT_NE(coverage_summary(capped.series).find("of 10 coarser windows of 1 series"), std::string::npos)
      << coverage_summary(capped.series);
}

TEST(ReportCoverage, AStoredCheckIsUsedNotRecomputed) {
  StudyReportData d = cubic_study(false);
  CoverageCheck stored;
  stored.status = "checked";
  stored.reference = 123.0;
  stored.judged = 7;
  stored.covered = 3;
  d.series[0].stored_coverage = stored;
  const ReportContent c = build_report_content(d, library_extrapolator({}));
  ASSERT_TRUE(c.series[0].coverage.has_value());
  EXPECT_EQ(c.series[0].coverage->judged, 7);
  EXPECT_TRUE(c.series[0].coverage->windows.empty());
}

TEST(ReportCoverage, NotMadeWhileGridsArePending) {
  const ReportContent c = content_with("capped", true);
  EXPECT_FALSE(c.series[0].coverage.has_value());
  EXPECT_TRUE(c.coverage_table.table.rows.empty());
  EXPECT_NE(coverage_summary(c.series).find("not yet made"), std::string::npos);
}

TEST(ReportCoverage, TheHtmlHasTheSectionAndItsReadingNote) {
  const std::string html = render_html(content_with("fm"));
  EXPECT_NE(html.find("id=\"coverage\""), std::string::npos);
  EXPECT_NE(html.find("Coverage self-check"), std::string::npos);
  EXPECT_NE(html.find("below the 95 %"), std::string::npos);
}

}  // namespace
}  // namespace gridfree
