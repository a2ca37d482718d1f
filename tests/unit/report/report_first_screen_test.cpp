// SPDX-License-Identifier: GPL-3.0-or-later
// The report's first screen (report/first_screen.h), the ranked concerns
// behind its attention list (series_concerns.h) and the series filter's
// fields (series_filter.h), on the synthetic study of report_test_data.h.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "report/first_screen.h"
#include "report/report_charts.h"
#include "report/report_tables.h"
#include "report/series_concerns.h"
#include "report/series_filter.h"
#include "report_test_data.h"

namespace gridfree {
namespace {

TEST(SeriesConcerns, EveryTroubledSeriesRankedByWhatMattersMost) {
  const auto series = test::synthetic_summaries();
  const auto c = series_concerns(series, 0.5, 2.1);
  // A converged on all grids: no concern. C (3 grids, insufficient) outranks
  // B (pre-asymptotic with a diverged grid).
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(series[c[0].series].label, "PC2 superbee fwhm6 bvk");
  EXPECT_EQ(c[0].weight, 50);
  EXPECT_EQ(series[c[1].series].label, "PC1 superbee fwhm6 hkl");
  EXPECT_EQ(c[1].weight, 30);
  ASSERT_EQ(c[1].concerns.size(), 2u);
  EXPECT_EQ(c[1].concerns[0], "1 failed grid (diverged at Δ* 0.25)");
  EXPECT_EQ(c[1].concerns[1], "verdict pre-asymptotic");
  EXPECT_NE(std::find(c[1].words.begin(), c[1].words.end(), "failed"), c[1].words.end());
  // An order outside the declared range is a concern of its own.
  const auto narrow = series_concerns(series, 1.5, 2.1);
  ASSERT_EQ(narrow.size(), 3u);  // A's p = 1 now lies outside
  EXPECT_EQ(narrow.back().concerns.back(), "order p = 1 outside the declared range [1.5, 2.1]");
}

TEST(FirstScreen, AnswersWithF0AndU1ThenAttention) {
  ReportContent c;
  c.series = test::synthetic_summaries();
  c.data.p_low = 0.5;
  c.data.p_high = 2.1;
  const FirstScreen f = first_screen(c);
  EXPECT_EQ(f.counts, "3 series: 1 converged, 1 pre-asymptotic, 1 insufficient_grids (1 with grids still to run)");
  ASSERT_EQ(f.rows.size(), 3u);
  // The stand-in gives no U₀: f0 to the digits of U₁ = 1.25·4 + 0.5 = 5.5.
  EXPECT_EQ(f.rows[0].f0, "1000.0 (no U₀)");
  EXPECT_EQ(f.rows[0].f1, "1004.0 ± 5.5 at Δ* 0.5");
  EXPECT_EQ(f.rows[2].f0, "—");
  EXPECT_EQ(f.more_series, 0u);
  EXPECT_EQ(f.attention_total, 2u);
  ASSERT_EQ(f.attention.size(), 2u);
  EXPECT_EQ(f.attention[0].label, "PC2 superbee fwhm6 bvk");
  const std::string html = first_screen_html(c);
  // The answer comes before the attention list, each series linked.
  EXPECT_LT(html.find("id=\"answer\""), html.find("id=\"attention\""));
  EXPECT_NE(html.find("1004.0 ± 5.5"), std::string::npos);
  EXPECT_NE(html.find("href=\"#v-PC1_superbee_fwhm6_hkl\""), std::string::npos);
  EXPECT_NE(first_screen_markdown(c).find("| PC1 superbee fwhm6 bvk | 1000.0 (no U₀) | converged |"),
            std::string::npos);
}

TEST(SeriesFilter, FieldsAreTheSeriesTableColumnsWithoutProse) {
  const Table t = series_table(test::synthetic_summaries(), 0.5, 2.1);
  const auto fields = series_filter_fields(t);
  for (const char* f : {"series", "f0", "verdict", "attention", "failed", "drag"})
    EXPECT_NE(std::find(fields.begin(), fields.end(), f), fields.end()) << f;
  EXPECT_EQ(std::find(fields.begin(), fields.end(), "verdict_reasons"), fields.end());
  const std::string script = series_filter_script(t);
  EXPECT_EQ(script.find("</", 1), script.rfind("</script>"));  // no early end of the script
  EXPECT_NE(script.find("\"pre-asymptotic\""), std::string::npos);
}

// The speed-accuracy charts of a summary draw the series that most need a
// look (with an f0: C has none) and then the cheapest converged ones.
TEST(SpeedAccuracySelection, WorstWithAnF0ThenCheapestConverged) {
  const auto series = test::synthetic_summaries();
  EXPECT_EQ(speed_accuracy_selection(series, 0.5, 2.1, 4, 3), (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(speed_accuracy_selection(series, 0.5, 2.1, 0, 3), (std::vector<std::size_t>{0}));
  EXPECT_EQ(speed_accuracy_selection(series, 0.5, 2.1, 4, 0), (std::vector<std::size_t>{1}));
}

}  // namespace
}  // namespace gridfree
