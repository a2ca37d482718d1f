// SPDX-License-Identifier: GPL-3.0-or-later
// Comparisons of an external study's series (report/differences.h,
// report/ensemble_stats.h, report/ensemble_budget.h): the study's own
// factors and the case pair series, a quantity never pairs with another,
// and an ensemble averages each configuration (levels × quantity) over its
// instances. Hand-made series with f0 chosen so every number is exact.
#include <gtest/gtest.h>

#include <cmath>

#include "report/differences.h"
#include "report/ensemble_budget.h"
#include "report/ensemble_stats.h"

namespace gridfree {
namespace external_comparisons_test {

// An external series of case c at scheme level `scheme` for quantity q,
// extrapolated to f0 with U = u on its one grid (h = 0.1).
SeriesSummary external_summary(const std::string& c, const std::string& scheme, const std::string& q, double f0,
                               double u = 0.01) {
  SeriesSummary s;
  s.series.case_name = c;
  s.series.quantity = q;
  s.series.levels = {{"scheme", scheme}};
  s.label = s.series.label();
  ExtrapolationView e;
  e.status = "ok";
  e.f0 = f0;
  e.grids = {{0.1, f0, f0, u, u / f0}};
  s.extrapolation = e;
  s.verdict = "converged";
  return s;
}

TEST(ExternalComparisons, OwnFactorsAndCasePairWithinOneQuantity) {
  const std::vector<SeriesSummary> s = {
      external_summary("a", "upwind", "T", 1.0), external_summary("a", "linear", "T", 3.0),
      external_summary("b", "upwind", "T", 2.0), external_summary("a", "upwind", "flux", 10.0),
      external_summary("a", "linear", "flux", 30.0)};
  EXPECT_EQ(s[0].label, "a scheme=upwind T");
  const auto factors = series_factors(s[1].series);
  ASSERT_EQ(factors.size(), 2u);
  EXPECT_EQ(factors[1], (std::pair<std::string, std::string>{"scheme", "linear"}));
  const auto d = one_factor_differences(s);
  // a up–a lin (T), a up–b up (T), a up–a lin (flux); nothing across T and flux.
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].factor, "scheme");
  EXPECT_EQ(d[0].value_a, "upwind");
  EXPECT_EQ(d[0].value_b, "linear");
  EXPECT_DOUBLE_EQ(*d[0].relative, 2.0 * 2 / 4);
  EXPECT_EQ(d[1].factor, "case");
  EXPECT_EQ(d[1].b, 2u);
  EXPECT_EQ(d[2].factor, "scheme");
  EXPECT_EQ(d[2].a, 3u);
  EXPECT_DOUBLE_EQ(*d[2].relative, 2.0 * 20 / 40);
  for (const auto& x : d) EXPECT_EQ(s[x.a].series.quantity, s[x.b].series.quantity);
}

// Instances t1..t3: upwind f0 = 1, 2, 3 (mean 2, s = 1); linear f0 = 4, 4, 4
// (mean 4, s = 0); model form upwind vs linear = 2·|2 − 4| / 6 = 2/3.
TEST(ExternalComparisons, EnsembleAveragesEachConfigurationOverItsInstances) {
  const std::vector<SeriesSummary> s = {
      external_summary("t1", "upwind", "T", 1.0), external_summary("t2", "upwind", "T", 2.0),
      external_summary("t3", "upwind", "T", 3.0), external_summary("t1", "linear", "T", 4.0),
      external_summary("t2", "linear", "T", 4.0), external_summary("t3", "linear", "T", 4.0),
      external_summary("t1", "upwind", "flux", 9.0)};
  const std::map<std::string, std::vector<std::string>> ensembles = {{"seeds", {"t1", "t2", "t3"}}};
  const auto configs = ensemble_configs(s, ensembles);
  ASSERT_EQ(configs.size(), 3u);  // upwind T, linear T, upwind flux
  EXPECT_EQ(configs[0].label(), "seeds: scheme=upwind T");
  EXPECT_EQ(configs[0].members.size(), 3u);
  EXPECT_DOUBLE_EQ(configs[0].f0->mean, 2.0);
  EXPECT_DOUBLE_EQ(*configs[0].f0->sd, 1.0);
  EXPECT_DOUBLE_EQ(configs[1].f0->mean, 4.0);
  EXPECT_EQ(configs[2].members.size(), 1u);
  const auto m = model_form_differences(configs);
  ASSERT_EQ(m.size(), 1u);  // the flux configuration has no partner of its quantity
  EXPECT_EQ(m[0].factor, "scheme");
  EXPECT_EQ(m[0].value_a, "upwind");
  EXPECT_DOUBLE_EQ(*m[0].relative, 2.0 / 3.0);
  const auto rows = budget_rows(configs, m);
  ASSERT_FALSE(rows.empty());
  EXPECT_DOUBLE_EQ(*rows[0].model_form, 2.0 / 3.0);
  EXPECT_EQ(rows[0].model_form_pair, "scheme upwind vs linear");
  EXPECT_DOUBLE_EQ(*rows[0].spread, 0.5);  // s/|mean| = 1/2
}

}  // namespace external_comparisons_test
}  // namespace gridfree
