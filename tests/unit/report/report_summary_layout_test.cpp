// SPDX-License-Identifier: GPL-3.0-or-later
// The summary layout of a study too large for one page (report_layout.h):
// the study page summarises and links one page per series; a rewrite with
// nothing changed rewrites no series file, one changed series rewrites its
// own files only; the pieces (one-factor pairs by grouping, quantiles,
// sampling, worst series, verdict counts, the extrapolation memo) checked
// against direct computations.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "report/chart_rde_bands.h"
#include "report/differences.h"
#include "report/extrapolation_memo.h"
#include "report/report.h"
#include "report/report_charts.h"
#include "report/report_content.h"
#include "report/report_layout.h"
#include "report/series_concerns.h"
#include "report/verdict_counts.h"
#include "report_test_data.h"
#include "test_files.h"
#include "xml_check.h"

namespace gridfree {
namespace {

namespace fs = std::filesystem;

// cases × drags × fwhms series of 6 grids, f = f0 + k h^1.5 (+ a bump on
// `bumped` series' finest grid).
StudyReportData layout_study(int cases, const std::vector<std::string>& drags, const std::vector<double>& fwhms,
                             long long bumped = -1) {
  StudyReportData d;
  d.study_name = "layout";
  d.status = "done";
  d.export_charts = false;
  long long id = 0;
  for (int c = 0; c < cases; ++c)
    for (const auto& drag : drags)
      for (double fwhm : fwhms) {
        SeriesData s{++id, "B" + std::to_string(c), "superbee", drag, "diffusion", fwhm, "done", {}, {}};
        for (double h : {2.0, 1.6, 1.28, 1.024, 0.8192, 0.65536}) {
          GridPoint g;
          g.job_hash = std::to_string(id) + "/" + std::to_string(h);
          g.delta_star = h;
          g.nx = g.ny = g.nz = static_cast<int>(10 / h);
          g.status = "converged";
          g.iterations = 10;
          g.cpu_s = 1 / h;
          g.dp_star = 1000 + static_cast<double>(id) + (2 + static_cast<double>(id % 3)) * std::pow(h, 1.5) +
                      (id == bumped && h < 0.7 ? 0.01 : 0.0);
          s.grids.push_back(g);
        }
        d.series.push_back(std::move(s));
      }
  return d;
}

ino_t inode_of(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

std::map<std::string, ino_t> inodes_under(const fs::path& dir) {
  std::map<std::string, ino_t> out;
  for (const auto& e : fs::directory_iterator(dir)) out[e.path().filename().string()] = inode_of(e.path());
  return out;
}

class SummaryLayout : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("gridfree-layout-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SummaryLayout, StudyPageSummarisesAndLinksAPagePerSeries) {
  const auto data = layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6});  // 30 series > kFullPageSeries
  ASSERT_GT(data.series.size(), kFullPageSeries);
  write_study_report(data, dir_, test::fake_extrapolation);
  const std::string html = test_support::slurp(dir_ / "report.html");
  const std::string problem = test::xml_problem(html, true);
  EXPECT_EQ(problem, "");
  if (!problem.empty()) {
    const auto at = std::stoul(problem.substr(problem.rfind(' ') + 1));
    ADD_FAILURE() << html.substr(at > 200 ? at - 200 : 0, 260);
  }
  // No per-series chart on the study page; the aggregated RDE charts, one per
  // factor of 2–8 levels (drag, fwhm_dp; the 5 cases too).
  EXPECT_EQ(html.find("fig1_"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "fig2_rde_drag.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "fig2_rde_fwhm_dp.svg"));
  EXPECT_TRUE(fs::exists(dir_ / "fig2_rde_case.svg"));
  EXPECT_FALSE(fs::exists(dir_ / "fig2_rde.svg"));
  EXPECT_NE(html.find("id=\"answer\""), std::string::npos);  // the first screen (first_screen.h)
  EXPECT_NE(html.find("id=\"series-filter\""), std::string::npos);
  // Every series page exists, is well formed, links back, and is linked from the study page.
  int pages = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "series")) {
    if (e.path().extension() != ".html") continue;
    ++pages;
    const std::string page = test_support::slurp(e.path());
    EXPECT_EQ(test::xml_problem(page, true), "") << e.path();
    EXPECT_NE(page.find("href=\"../report.html\""), std::string::npos);
    EXPECT_NE(page.find("<svg"), std::string::npos);
    EXPECT_NE(html.find("href=\"series/" + e.path().filename().string() + "\""), std::string::npos) << e.path();
  }
  EXPECT_EQ(pages, 30);
  // Markdown: the worst series linked to their pages, no per-series chart.
  const std::string md = test_support::slurp(dir_ / "report.md");
  EXPECT_NE(md.find("](series/"), std::string::npos);
  EXPECT_EQ(md.find("fig1_"), std::string::npos);
}

TEST_F(SummaryLayout, ARewriteTouchesOnlyWhatChanged) {
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}), dir_, test::fake_extrapolation);
  const auto before = inodes_under(dir_ / "series");
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}), dir_, test::fake_extrapolation);
  EXPECT_EQ(inodes_under(dir_ / "series"), before);  // nothing rewritten
  // Series 7's finest grid moves: its page and Fig. 1 are rewritten, no other file.
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}, 7), dir_, test::fake_extrapolation);
  const auto after = inodes_under(dir_ / "series");
  std::vector<std::string> changed;
  for (const auto& [name, inode] : after)
    if (before.at(name) != inode) changed.push_back(name);
  ASSERT_FALSE(changed.empty());
  for (const auto& name : changed) EXPECT_NE(name.find("07_B"), std::string::npos) << name;
}

TEST_F(SummaryLayout, ALiveWritersTemporaryInSeriesIsLeftAlone) {
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}), dir_, test::fake_extrapolation);
  const fs::path live = dir_ / "series" / (".page.html.tmp-" + std::to_string(::getpid()) + "-1");
  std::ofstream(live) << "half";
  const fs::path stale_page = dir_ / "series" / "99_gone.html";
  std::ofstream(stale_page) << "a series no longer in the study";
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}), dir_, test::fake_extrapolation);
  EXPECT_TRUE(fs::exists(live));  // this process is alive: its temporary is in flight
  EXPECT_FALSE(fs::exists(stale_page));
}

TEST_F(SummaryLayout, AStudyBackOnOnePageKeepsNoSeriesPages) {
  write_study_report(layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6}), dir_, test::fake_extrapolation);
  ASSERT_TRUE(fs::exists(dir_ / "series"));
  write_study_report(layout_study(2, {"bvk", "hkl"}, {3}), dir_, test::fake_extrapolation);  // 4 series
  EXPECT_FALSE(fs::exists(dir_ / "series"));
  EXPECT_TRUE(fs::exists(dir_ / "fig2_rde.svg"));
  EXPECT_FALSE(fs::exists(dir_ / "fig2_rde_drag.svg"));
}

// Against the definition: every pair of series that differ in exactly one factor.
TEST(OneFactorPairs, GroupingFindsExactlyTheAllPairsAnswer) {
  auto data = layout_study(3, {"bvk", "hkl", "wen_yu"}, {3, 6, 12});
  data.series.erase(data.series.begin() + 4);  // an incomplete factorial
  data.series.erase(data.series.begin() + 10);
  const auto summaries = summarize_series(data, test::fake_extrapolation);
  std::vector<std::pair<std::size_t, std::size_t>> expected;
  for (std::size_t a = 0; a < summaries.size(); ++a)
    for (std::size_t b = a + 1; b < summaries.size(); ++b) {
      const auto fa = series_factors(summaries[a].series), fb = series_factors(summaries[b].series);
      int differing = 0;
      for (std::size_t k = 0; k < fa.size(); ++k) differing += fa[k] != fb[k] ? 1 : 0;
      if (differing == 1) expected.emplace_back(a, b);
    }
  std::vector<std::pair<std::size_t, std::size_t>> got;
  for (const auto& d : one_factor_differences(summaries)) got.emplace_back(d.a, d.b);
  EXPECT_EQ(got, expected);
  EXPECT_GT(expected.size(), 50u);
}

TEST(OneFactorPairs, AFactorOfManyLevelsPairsNoSeries) {
  const auto many = summarize_series(layout_study(13, {"bvk", "hkl"}, {3}), test::fake_extrapolation);
  for (const auto& d : one_factor_differences(many)) EXPECT_EQ(d.factor, "drag");
  EXPECT_EQ(one_factor_differences(many).size(), 13u);  // bvk–hkl in each of the 13 cases
  const auto twelve = summarize_series(layout_study(12, {"bvk"}, {3}), test::fake_extrapolation);
  EXPECT_EQ(one_factor_differences(twelve).size(), 66u);  // 12·11/2 case pairs
}

TEST(RdeBands, QuantilesInterpolateBetweenOrderStatistics) {
  const std::vector<double> v = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile(v, 0.1), 1.3);  // position 0.3 between 1 and 2
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(RdeBands, SampledSeriesAreEvenlySpacedWithBothEnds) {
  const auto s = sample_indices(540, 24);
  ASSERT_EQ(s.size(), 24u);
  EXPECT_EQ(s.front(), 0u);
  EXPECT_EQ(s.back(), 539u);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_GT(s[i], s[i - 1]);
    EXPECT_LE(s[i] - s[i - 1], 24u);  // 539 / 23 = 23.4
  }
  EXPECT_EQ(sample_indices(5, 24).size(), 5u);
}

TEST(VerdictCounts, LevelsAddUpAndTheWorstComeFirst) {
  const auto summaries =
      summarize_series(layout_study(2, {"bvk", "hkl"}, {3, 6}), test::fake_extrapolation);  // 8 series
  const Table t = verdict_count_table(summaries);
  ASSERT_EQ(t.rows.front()[0].exact, "all");
  EXPECT_EQ(t.rows.front()[2].exact, "8");
  std::map<std::string, int> per_factor;
  for (std::size_t r = 1; r < t.rows.size(); ++r) per_factor[t.rows[r][0].exact] += std::stoi(t.rows[r][2].exact);
  for (const auto& [factor, n] : per_factor) EXPECT_EQ(n, 8) << factor;
  EXPECT_EQ(per_factor.size(), 3u);  // case, fwhm_dp, drag (convection and deposition have one level)

}

// The Markdown report of a large study lists the series that need a look as
// the Attention list ranks them, not by finest-grid RDE: a series whose
// finest grid diverged (its RDE from the remaining grids as small as its
// neighbours') comes before converged series whose only concern is none,
// and a study with more concerns than kWorstSeries says how many more.
// A diverged grid finer than the series' converged ones (its RDE unchanged).
void add_failed_grid(SeriesData& s) {
  GridPoint bad = s.grids.front();
  bad.job_hash += "/finer";
  bad.delta_star = 0.5;
  bad.status = "diverged";
  bad.dp_star.reset();
  bad.reason = "residual grew";
  s.grids.push_back(bad);
}

std::string needs_a_look_section(const StudyReportData& data) {
  const ReportContent c = build_report_content(data, test::fake_extrapolation);
  EXPECT_EQ(c.layout, ReportLayout::summary);
  const std::string md = render_markdown(c);
  const auto at = md.find("### Series that need a look, worst first");
  EXPECT_NE(at, std::string::npos);
  return at == std::string::npos ? std::string() : md.substr(at, md.find("\n## ", at) - at);
}

TEST(SummaryMarkdown, NeedsALookIsRankedLikeAttention) {
  // 30 series (summary layout), all converged by the stand-in; one with a
  // diverged grid: it is listed, with why, and no converged series is.
  auto data = layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6});
  add_failed_grid(data.series[7]);
  std::string list = needs_a_look_section(data);
  EXPECT_NE(list.find("**[" + data.series[7].label() + "]("), std::string::npos) << list;
  EXPECT_NE(list.find("Needs a look: 1 failed grid (diverged at Δ* 0.5)"), std::string::npos) << list;
  EXPECT_EQ(list.find("**[" + data.series[6].label() + "]("), std::string::npos) << list;
  EXPECT_EQ(list.find("more of"), std::string::npos);
  // 25 series with a failed grid: the first kWorstSeries and "… and 5 more of 25".
  data = layout_study(5, {"bvk", "hkl", "wen_yu"}, {3, 6});
  for (std::size_t i = 0; i < 25; ++i) add_failed_grid(data.series[i]);
  list = needs_a_look_section(data);
  EXPECT_NE(list.find("- … and " + std::to_string(25 - kWorstSeries) + " more of 25"), std::string::npos) << list;
  EXPECT_EQ(list.find("**[" + data.series[27].label() + "]("), std::string::npos);
}

TEST(ExtrapolationMemoTest, SameInputsAreNotExtrapolatedTwiceAndUnusedEntriesGo) {
  int calls = 0;
  ExtrapolationMemo memo;
  const Extrapolator counted = memo.wrap([&calls](const std::vector<double>& h, const std::vector<double>&) {
    ++calls;
    return nlohmann::json{{"n", h.size()}};
  });
  const std::vector<double> h = {1, 2, 3, 4}, f = {10, 11, 12, 13};
  auto g = f;
  g.back() = std::nextafter(13.0, 14.0);  // one bit differs: a new extrapolation
  EXPECT_EQ(counted(h, f)["n"], 4);
  counted(h, f);
  counted(h, g);
  EXPECT_EQ(calls, 2);
  memo.end_write();
  counted(h, f);  // used by this write: kept
  memo.end_write();
  EXPECT_EQ(memo.size(), 1u);  // (h, g) was not used by the last write
  counted(h, f);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(memo.hits(), 3);
}

}  // namespace
}  // namespace gridfree
