// SPDX-License-Identifier: GPL-3.0-or-later
// Ensemble statistics and the uncertainty budget (report/ensemble_stats.h,
// report/ensemble_budget.h, report/report_ensembles.h) on hand-made series:
// three instances × two drag laws with known f0 and U, checked against
// values computed by hand (and the one-pass formula in long double), the
// averaging rule for instances without a converged verdict, the budget's
// dominance rule, and the rendered section.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "report/ensemble_budget.h"
#include "report/ensemble_stats.h"
#include "report/report_content.h"
#include "report/report_ensembles.h"

namespace gridfree {
namespace {

// A series of case c and drag d whose extrapolation has f0 and, at h = 1 and
// h = 2, U = u1 and u2 (RDE = U/|f0|).
SeriesSummary summary(const std::string& c, const std::string& drag, double f0, double u1, double u2,
                      const std::string& verdict = "converged") {
  SeriesSummary s;
  s.series.case_name = c;
  s.series.convection = "superbee";
  s.series.drag = drag;
  s.series.deposition = "diffusion";
  s.series.fwhm_dp = 6;
  s.label = s.series.label();
  ExtrapolationView e;
  e.status = "ok";
  e.f0 = f0;
  e.grids = {{1.0, f0, f0, u1, u1 / f0}, {2.0, f0, f0, u2, u2 / f0}};
  s.extrapolation = e;
  s.verdict = verdict;
  return s;
}

const std::map<std::string, std::vector<std::string>> kEnsembles = {{"snap", {"t1", "t2", "t3"}}};

// t1..t3 with bvk: f0 1000, 1002, 1010; with hkl: 1500, 1530, 1440 (t3 pre-asymptotic).
std::vector<SeriesSummary> hand_made() {
  return {summary("t1", "bvk", 1000, 2, 6),  summary("t2", "bvk", 1002, 4, 8),
          summary("t3", "bvk", 1010, 3, 10), summary("t1", "hkl", 1500, 3, 30),
          summary("t2", "hkl", 1530, 6, 60), summary("t3", "hkl", 1440, 9, 90, "pre-asymptotic"),
          summary("other", "bvk", 5000, 1, 1)};
}

TEST(EnsembleStats, SampleStatisticsByHand) {
  // 1000, 1002, 1004, 1010: mean 1004, deviations −4 −2 0 6, Σd² = 56, s² = 56/3.
  const auto s = sample_stats({1000, 1002, 1004, 1010, NAN});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->n, 4);  // NaN left out
  EXPECT_DOUBLE_EQ(s->mean, 1004);
  EXPECT_DOUBLE_EQ(s->min, 1000);
  EXPECT_DOUBLE_EQ(s->max, 1010);
  EXPECT_NEAR(*s->sd, std::sqrt(56.0 / 3.0), 1e-12);
  EXPECT_NEAR(*s->sem, std::sqrt(56.0 / 3.0) / 2.0, 1e-12);
  EXPECT_NEAR(*s->relative_sd(), std::sqrt(56.0 / 3.0) / 1004.0, 1e-15);
  const auto one = sample_stats({7});
  EXPECT_FALSE(one->sd);  // one value: no spread
  EXPECT_FALSE(sample_stats({}));
}

TEST(EnsembleStats, AgreesWithOnePassFormulaInLongDouble) {
  const std::vector<double> x = {1017.3, 1016.1, 1019.8, 1015.2, 1018.4, 1016.9};
  long double sum = 0, sum2 = 0;
  for (double v : x) {
    sum += v;
    sum2 += static_cast<long double>(v) * v;
  }
  const long double n = x.size(), mean = sum / n;
  const double sd = static_cast<double>(std::sqrt((sum2 - n * mean * mean) / (n - 1)));
  const auto s = sample_stats(x);
  EXPECT_NEAR(s->mean, static_cast<double>(mean), 1e-12);
  // Σx² ≈ 6.2e6 in long double (64-bit mantissa): cancellation leaves ~1e-12 relative in s² here.
  EXPECT_NEAR(*s->sd, sd, 1e-9);
}

TEST(EnsembleStats, ConfigurationsAveragedOverInstances) {
  const auto configs = ensemble_configs(hand_made(), kEnsembles);
  ASSERT_EQ(configs.size(), 2u);  // "other" is in no ensemble
  const auto& bvk = configs[0];
  EXPECT_EQ(bvk.drag, "bvk");
  EXPECT_EQ(bvk.instances, (std::vector<std::string>{"t1", "t2", "t3"}));
  EXPECT_EQ(bvk.converged, 3);
  EXPECT_FALSE(bvk.flagged());
  // 1000, 1002, 1010: mean 1004, deviations −4 −2 6, Σd² = 56, s = sqrt(28).
  EXPECT_DOUBLE_EQ(bvk.f0->mean, 1004);
  EXPECT_NEAR(*bvk.f0->sd, std::sqrt(28.0), 1e-12);
  EXPECT_NEAR(*bvk.f0->sem, std::sqrt(28.0 / 3.0), 1e-12);
  ASSERT_EQ(bvk.grids.size(), 2u);
  EXPECT_DOUBLE_EQ(bvk.grids[0].delta_star, 1.0);
  // Mean RDE at h = 1: (2/1000 + 4/1002 + 3/1010)/3; mean U (2 + 4 + 3)/3 = 3.
  EXPECT_NEAR(bvk.grids[0].rde_stats->mean, (2 / 1000.0 + 4 / 1002.0 + 3 / 1010.0) / 3, 1e-15);
  EXPECT_DOUBLE_EQ(bvk.grids[0].u_stats->mean, 3);
  const auto& hkl = configs[1];
  EXPECT_EQ(hkl.converged, 2);
  EXPECT_TRUE(hkl.flagged());  // t3 pre-asymptotic: still averaged, flagged
  EXPECT_EQ(hkl.f0->n, 3);
  EXPECT_DOUBLE_EQ(hkl.f0->mean, 1490);
}

TEST(EnsembleStats, InstanceWithoutF0LeftOutAndNamed) {
  auto s = hand_made();
  s[1].extrapolation->f0.reset();
  const auto configs = ensemble_configs(s, kEnsembles);
  EXPECT_EQ(configs[0].without_f0, (std::vector<std::string>{"t2"}));
  EXPECT_EQ(configs[0].f0->n, 2);
  EXPECT_DOUBLE_EQ(configs[0].f0->mean, 1005);
}

TEST(EnsembleBudget, ModelFormAndDominance) {
  const auto configs = ensemble_configs(hand_made(), kEnsembles);
  const auto diffs = model_form_differences(configs);
  ASSERT_EQ(diffs.size(), 1u);
  EXPECT_EQ(diffs[0].factor, "drag");
  // 2|1004 − 1490| / (1004 + 1490) = 972/2494.
  EXPECT_NEAR(*diffs[0].relative, 972.0 / 2494.0, 1e-15);
  const auto rows = budget_rows(configs, diffs);
  ASSERT_EQ(rows.size(), 4u);
  // bvk at h = 1: D ≈ 0.3 %, M ≈ 39 %, S = sqrt(28)/1004 ≈ 0.53 % → model form.
  EXPECT_EQ(rows[0].dominant, "model form");
  EXPECT_NEAR(*rows[0].spread, std::sqrt(28.0) / 1004.0, 1e-15);
  EXPECT_EQ(rows[0].model_form_pair, "drag bvk vs hkl");
  EXPECT_EQ(dominant_source(0.03, std::nullopt, 0.01), "discretization");
  EXPECT_EQ(dominant_source(0.01, std::nullopt, 0.02), "instance spread");
  EXPECT_EQ(dominant_source(std::nullopt, std::nullopt, std::nullopt), "");
}

TEST(EnsembleBudget, WithoutModelFormSpreadAgainstDiscretization) {
  auto s = hand_made();
  s.resize(3);  // bvk only: no model-form pair
  const auto configs = ensemble_configs(s, kEnsembles);
  const auto rows = budget_rows(configs, model_form_differences(configs));
  // S = sqrt(28)/1004 ≈ 0.527 %. h = 1: D = mean(0.2, 0.399, 0.297) % ≈ 0.299 % → spread;
  // h = 2: D = mean(0.6, 0.798, 0.990) % ≈ 0.796 % → discretization.
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_FALSE(rows[0].model_form);
  EXPECT_EQ(rows[0].dominant, "instance spread");
  EXPECT_EQ(rows[1].dominant, "discretization");
  const auto sentences = budget_sentences(configs, rows);
  ASSERT_EQ(sentences.size(), 1u);
  EXPECT_NE(sentences[0].find("instance spread dominates at Δ* 1"), std::string::npos) << sentences[0];
  EXPECT_NE(sentences[0].find("discretization dominates at Δ* 2"), std::string::npos) << sentences[0];
}

TEST(EnsembleSectionRender, TablesChartAndText) {
  ReportContent c;
  c.series = hand_made();
  c.ensembles = ensemble_section(c.series, kEnsembles);
  ASSERT_FALSE(c.ensembles.empty());
  EXPECT_EQ(c.ensembles.summary_table.rows.size(), 2u);
  EXPECT_EQ(c.ensembles.budget_table.rows.size(), 4u);
  ASSERT_EQ(c.ensembles.charts.size(), 1u);
  EXPECT_EQ(c.ensembles.charts[0].file, "budget_snap.svg");
  EXPECT_EQ(c.ensembles.charts[0].chart.series.size(), 2u);
  // Every dashed line has its own colour (the legend tells them apart): one
  // spread line per configuration in its colour, the model form in black.
  const auto& hl = c.ensembles.charts[0].chart.hlines;
  ASSERT_EQ(hl.size(), 3u);
  std::set<int> colours;
  for (const auto& l : hl) colours.insert(l.colour);
  EXPECT_EQ(colours.size(), hl.size());
  for (const auto& l : hl) {
    if (l.label.rfind("model form", 0) == 0) {
      EXPECT_EQ(l.colour, 6) << l.label;
    }
  }
  const std::string md = ensembles_markdown(c);
  EXPECT_NE(md.find("## Ensembles and uncertainty budget"), std::string::npos);
  EXPECT_NE(md.find("1 of 3 instances not converged"), std::string::npos);
  const std::string html = ensembles_html(c);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  ReportContent none;
  EXPECT_EQ(ensembles_markdown(none), "");
}

}  // namespace
}  // namespace gridfree
